"""polyplan.Experiment and polyplan.Results: `polyplan benchmark` from Python.

An experiment is problems x planner entries x seeds (the experiment file's format, docs/benchmark.md);
each cell is one run: the planner built for its problem with its options and seed, and asked the
problem's query once. Runs go on threads, each alone in its thread; the results are the records of
results.json, as numpy columns or a pandas DataFrame, and the files the program writes.
"""

import decimal
import inspect
import json as _json
import math
import numbers
import operator
import os
import sys
import time

import numpy as np

from . import _polyplan, cluster
from ._arguments import path as _path, shown as _shown
from ._polyplan import InputError


class Experiment:
    """An experiment, from a dict in the experiment file's format or from a file::

        exp = polyplan.Experiment({
            "name": "rrt-vs-rrtstar",
            "problems": [{"name": "office", "file": "data/worlds/office.json"}],
            "planners": [{"name": "rrt", "planner": "rrt"},
                         {"name": "rrtstar", "planner": "rrtstar", "options": {"k": 11}}],
            "seeds": [1, 2, 3], "time_limit": 1})
        results = exp.run(threads=2)

    A dict's problem files are relative to `folder` (the working folder when None), a file's to
    the file's folder. Bad input raises InputError naming the object, as the program does."""

    def __init__(self, spec, folder=None):
        if isinstance(spec, _polyplan._ExperimentSpec):
            self._spec = spec
            return
        if not isinstance(spec, dict):
            raise InputError(f"Experiment: expected a dict in the experiment file's format, got {type(spec).__name__}")
        from . import _json_value
        plain = _json_value(spec, "", exact=False)
        _check_texts(plain, "")
        text = _json.dumps(plain)
        name = os.path.join(_path(folder, "Experiment: folder"), "<dict>") if folder is not None else "<dict>"
        self._spec = _polyplan._parse_experiment(text, name)

    @classmethod
    def from_file(cls, path):
        """The experiment file at `path` (JSON)."""
        return cls(_polyplan._read_experiment(_path(path, "Experiment.from_file", "file")))

    @property
    def name(self):
        """The experiment's name (its file's "name")."""
        return self._spec.name

    @property
    def runs(self):
        """How many runs it has: problems x planner entries x seeds."""
        return self._spec.runs

    @property
    def problems(self):
        """The problems' names, in the experiment's order."""
        return self._spec.problems

    @property
    def planners(self):
        """The planner entries' names."""
        return self._spec.planners

    def run(self, threads=1, progress=True, out=None, seeds=None, time_limit=None, client=None, resume=False):
        """Runs every cell on `threads` threads (0: one per core), or as one task per run on a Dask
        cluster's `client` (a distributed.Client), and returns its Results.

        progress: a line on stderr that counts the runs (True), a function progress(done, total)
        called after each run, or False. out: a folder to write the program's files to as well
        (Results.write), where each run's record is kept as it comes (runs.jsonl), so that Ctrl-C
        loses no run made. resume: make only the runs missing from `out`, an interrupted run's
        folder. seeds: only the first N seeds; time_limit: seconds per run instead of the
        experiment's, its cost times scaled alike (as `polyplan benchmark --seeds --time-limit`).

        Ctrl-C during a run with a client or an `out` folder raises ExperimentInterrupted (a
        KeyboardInterrupt) holding the Results of the runs made, written to `out` first, marked
        incomplete."""
        threads = _whole(threads, "threads", 0, 256)
        seeds = 0 if seeds is None else _whole(seeds, "seeds", 1, None)
        if seeds > len(self._spec.seeds):  # here: an int beyond 64 bits cannot reach the compiled half
            raise InputError(f"seeds {_shown(seeds)}: the experiment has {len(self._spec.seeds)} seeds")
        time_limit = 0.0 if time_limit is None else self._time_limit(time_limit)
        report = _progress(progress)
        if out is not None:
            out = _path(out, "Experiment.run: out")
            if os.path.exists(out) and not os.path.isdir(out):
                raise InputError(f"Experiment.run: out: {out}: not a folder")
        if client is None and out is None:
            if resume:
                raise InputError("Experiment.run: resume: needs out, the folder of the run to resume")
            results = Results(_polyplan._run_experiment(self._spec, threads, seeds, time_limit, report))
        else:
            results = self._run_tasks(client, threads, seeds, time_limit, report, out, resume)
        if out is not None:
            results.write(out)
        if not results.complete and results.interrupted:
            raise cluster.ExperimentInterrupted(results)
        return results

    def _run_tasks(self, client, threads, seeds, time_limit, report, out, resume):
        """One task per run, on the client's cluster or on threads (cluster.py)."""
        if client is not None and not all(hasattr(client, name) for name in ("map", "cancel", "scheduler_info")):
            raise InputError(f"Experiment.run: client: expected a dask.distributed.Client, got {type(client).__name__}")
        spec = self._spec.scaled(seeds, time_limit)
        used = cluster.client_threads(client) if client is not None else threads or os.cpu_count() or 1
        started = cluster.started_at()
        records, seconds, interrupted = cluster.gather(spec, cluster.tasks_of(spec), client=client, threads=used,
                                                       progress=report, folder=out, resume=bool(resume))
        results = Results(_polyplan._experiment_outcome(spec, records, seconds, used, started, cluster.host()))
        results.interrupted = interrupted
        return results

    def _time_limit(self, given):
        """A run's time limit: a finite number of seconds > 0 (numpy's, a Fraction or a Decimal too);
        the compiled half refuses one that scales the cost times out of a double's range."""
        number = None
        if not isinstance(given, (bool, np.bool_)) and isinstance(given, (numbers.Real, decimal.Decimal)):
            try:
                number = float(given)
            except (OverflowError, ValueError, ArithmeticError):  # beyond a double; a signalling NaN
                number = math.inf
        if number is None or not number > 0 or not math.isfinite(number):
            raise InputError(f"time_limit {_shown(given)}: expected a finite number of seconds > 0")
        return number

    def __repr__(self):
        return (f"<polyplan.Experiment {self.name}: {len(self.problems)} problem(s) x {len(self.planners)} "
                f"planner entr(ies) x {len(self._spec.seeds)} seed(s), {self._spec.time_limit:g} s each>")


class Results:
    """An experiment's runs: `records` (one dict per run, as results.json's "runs": problem, planner,
    log_planner, seed, solved, status, time, setup_time, length, first_solution_time, improvements,
    cost_at, why_not, facts), `summary` (per problem and planner entry), `columns` (numpy arrays),
    `to_pandas()`, and `write(folder)` for the files `polyplan benchmark` writes."""

    def __init__(self, outcome):
        if not isinstance(outcome, _polyplan._ExperimentOutcome):
            raise InputError(f"Results: made by Experiment.run, not from {type(outcome).__name__}")
        self._outcome = outcome
        everything = outcome.json()
        self.records = everything["runs"]
        self.summary = everything["summary"]
        self.experiment = everything["experiment"]
        self.total_seconds = everything["total_seconds"]
        self.threads = everything["threads"]
        self.complete = everything["complete"]  # False when runs are missing (an interrupted run)
        self.experiment_runs = len(self.records) + everything["missing_runs"]
        self.interrupted = False  # Ctrl-C stopped the run that made them
        self.written = []  # the files the last write() wrote

    @property
    def columns(self):
        """One numpy array per field, a row per run: text as str arrays, seed as int64, solved as
        bool, times and lengths as float64 (NaN where a run has none), cost_at as (runs, cost
        times), and every numeric fact as "facts.NAME" (dotted as the CSV's columns)."""
        runs = self.records
        out = {name: np.array([r[name] for r in runs], dtype=str)
               for name in ("problem", "planner", "log_planner", "status")}
        out["why_not"] = np.array([r.get("why_not", "") for r in runs], dtype=str)
        out["seed"] = np.array([r["seed"] for r in runs], dtype=np.int64)
        out["solved"] = np.array([r["solved"] for r in runs], dtype=bool)
        for name in ("time", "setup_time", "length", "first_solution_time"):
            out[name] = _floats(r.get(name) for r in runs)
        out["cost_at"] = np.array([[_float(c) for c in r["cost_at"]] for r in runs], dtype=float).reshape(
            len(runs), len(self.experiment["cost_times"]))
        facts = [_numeric_facts(r.get("facts", {})) for r in runs]
        for name in dict.fromkeys(name for f in facts for name in f):
            out["facts." + name] = _floats(f.get(name) for f in facts)
        return out

    def to_pandas(self):
        """The runs as a pandas DataFrame, a row per run and a column per 1-d column (cost_at as
        cost_at_T, one per cost time T). Needs pandas (Debian: python3-pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Results.to_pandas needs pandas (Debian: python3-pandas)") from e
        columns = self.columns
        cost_at = columns.pop("cost_at")
        for i, t in enumerate(self.experiment["cost_times"]):
            columns[f"cost_at_{t:g}"] = cost_at[:, i]
        return pandas.DataFrame(columns)

    def write(self, folder):
        """Writes results.log (OMPL's benchmark log), results.json, results.csv, tables.md and the
        plots into `folder` (made when missing), as `polyplan benchmark --out` does; returns the
        paths written."""
        self.written = self._outcome.write(_path(folder, "Results.write: folder"))
        return self.written

    def __len__(self):
        return len(self.records)

    def __repr__(self):
        solved = sum(r["solved"] for r in self.records)
        missing = "" if self.complete else f" of {self.experiment_runs} (incomplete)"
        return f"<polyplan.Results {len(self.records)} runs{missing}, {solved} solved, {self.total_seconds:.3g} s>"


def _whole(value, name, least, most):
    if isinstance(value, (bool, np.bool_)) or isinstance(value, np.ndarray) and value.ndim:
        raise InputError(f"{name}: expected a whole number, got {type(value).__name__}")
    try:
        value = operator.index(value)
    except TypeError:
        raise InputError(f"{name}: expected a whole number, got {type(value).__name__}") from None
    if value < least or most is not None and value > most:
        raise InputError(f"{name} {_shown(value)}: expected a whole number in "
                         f"[{least}, {most if most is not None else 'inf'}]")
    return value


def _check_texts(value, where):
    """Refuses the strings of an experiment dict (plain JSON values) that cannot be passed on: not
    UTF-8 (a lone surrogate), or a problem's file with a NUL."""
    if isinstance(value, dict):
        for key, item in value.items():
            _check_texts(key, where or "experiment")
            _check_texts(item, f"{where}.{key}" if where else key)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            _check_texts(item, f"{where}[{i}]")
    elif isinstance(value, str):
        try:
            value.encode("utf-8")
        except UnicodeEncodeError:
            raise InputError(f"Experiment: {where}: {_shown(value)}: not UTF-8 (a lone surrogate)") from None
        if "\0" in value and where.endswith(".file"):
            raise InputError(f"Experiment: {where}: {_shown(value)}: a path cannot hold a NUL character")


def _progress(progress):
    """What reports progress: a _ProgressLine for True, the function given, or None."""
    if progress is True or isinstance(progress, np.bool_) and progress:
        return _ProgressLine("runs")
    if progress is None or progress is False or isinstance(progress, np.bool_):
        return None
    if not callable(progress):
        raise InputError(f"progress: expected True, False or a function (done, total), got {type(progress).__name__}")
    try:
        inspect.signature(progress).bind(0, 0)
    except TypeError:
        raise InputError(f"progress: {_shown(progress)}: cannot be called as progress(done, total)") from None
    except ValueError:  # a builtin without a signature: called as given
        pass
    return progress


def _float(value):
    return math.nan if value is None else float(value)


def _floats(values):
    return np.array([_float(v) for v in values], dtype=float)


def _numeric_facts(facts, prefix=""):
    """The facts' numbers (not flags, words, points) by dotted name."""
    out = {}
    for key, value in facts.items():
        if isinstance(value, dict):
            out.update(_numeric_facts(value, prefix + key + "."))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            out[prefix + key] = value
    return out


class _ProgressLine:
    """"runs: done/total, 12 s elapsed, about 30 s left" on stderr, at most once a second and at
    the end, as the program's progress bar."""

    def __init__(self, what):
        self.what, self.started, self.last = what, time.monotonic(), 0.0

    def __call__(self, done, total):
        self.tally(done, total)

    def tally(self, done, total, solved=None, failed=None, before=0):
        """The line, with the runs solved and failed when they are known; `before` of the runs done
        were made by an earlier run (a resumed one), so they do not set the pace."""
        now = time.monotonic()
        if now - self.last < 1.0 and done != total:
            return
        self.last = now
        elapsed = now - self.started
        left = f", about {elapsed / (done - before) * (total - done):.0f} s left" if before < done < total else ""
        counts = "" if solved is None else f", {solved} solved, {failed} failed"
        end = "\n" if done == total else ""
        sys.stderr.write(f"\r{self.what}: {done}/{total}{counts}, {elapsed:.0f} s elapsed{left}   {end}")
        sys.stderr.flush()
