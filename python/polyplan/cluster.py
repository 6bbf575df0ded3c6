"""An experiment's runs as tasks, one per run: on a Dask cluster (Experiment.run(client=...)), or on
this machine's threads when an interrupted experiment resumes. Each run's record is gathered as it
completes, kept in the results folder's runs.jsonl, and written at the end by the program's writers.

A task carries what its run needs — the problem file's text (and the WKT file a world names), the
planner entry with its options, the seed and the time limit — so that a worker needs polyplan
installed and nothing else: no shared file system. A run is the same on any worker: the same seed
gives the same path, only its times differ.

Nothing is lost. Dask reschedules the runs of a worker that dies; a run whose worker dies each time
it is tried (more often than the scheduler's allowed-failures, 1 on the local clusters made here)
is recorded as a failed run saying so. Ctrl-C cancels the runs not made and writes those gathered,
marked incomplete; runs.jsonl lets a resumed run make the missing ones only.
"""

import argparse
import concurrent.futures
import contextlib
import hashlib
import json as _json
import math
import os
import signal
import socket
import sys
import tempfile
import time
import uuid

from . import _polyplan
from ._arguments import shown as _shown
from ._polyplan import InputError

RECORDS = "runs.jsonl"  # in the results folder: a header line, then one run's record per line
# What the scheduler must be told (docs/benchmark.md says how for a cluster of several hosts).
SCHEDULER_CONFIG = {"distributed.scheduler.allowed-failures": 1, "distributed.scheduler.worker-saturation": 1.0}
FAILED = "the run failed"  # how a failed run's why_not begins (experiment_problem.hpp's mark_failed callers too)


class ExperimentInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped Experiment.run: `results` holds the runs made (Results.complete is False),
    already written to the results folder when one was given."""

    def __init__(self, results):
        super().__init__(f"interrupted: {len(results)} of {results.experiment_runs} runs made")
        self.results = results


def run_task(task):
    """One run, on whichever worker or thread: its record as JSON text."""
    source = task["source"]
    if task["attachments"]:
        source = _attached(task)
    return _polyplan._run_cell(task["text"], source, task["problem"], task["query"], task["entry"], task["planner"],
                               task["options"], task["seed"], task["time_limit"])


def tasks_of(spec):
    """The experiment's cells as tasks, in cell order."""
    files = {}
    tasks = []
    for problem, file, query, entry, planner, options, seed, time_limit in spec.cells():
        if file not in files:
            files[file] = _problem_files(problem, file)
        text, attachments = files[file]
        tasks.append({"problem": problem, "source": file, "query": query, "entry": entry, "planner": planner,
                      "options": options, "seed": seed, "time_limit": time_limit, "text": text,
                      "attachments": attachments})
    return tasks


def gather(spec, tasks, *, client=None, threads=1, progress=None, folder=None, resume=False, task=run_task):
    """Runs `tasks` (tasks_of(spec)) on `client` or on `threads` threads and returns the records
    (text, where it came from), the seconds it took and whether Ctrl-C stopped it (the records
    gathered so far come back). The records' file in `folder` (when given) gets each as it comes,
    after those made before when `resume`."""
    log = _RecordLog(spec, folder, resume)
    waiting = [t for t in tasks if (t["problem"], t["entry"], t["seed"]) not in log.made]
    tally = _Tally(len(tasks), log.records, progress)
    started = time.monotonic()
    pool = _Pool(client, threads)
    futures = pool.submit(task, waiting)
    interrupted = False
    try:
        for future in pool.as_completed(futures):
            record = _record_of(future, futures[future])
            log.add(record)
            tally.add(record)
    except KeyboardInterrupt:
        interrupted = True
        pool.cancel(futures)
    finally:
        pool.close()
        log.close()
    return log.records, time.monotonic() - started, interrupted


def local_cluster(workers):
    """A Dask LocalCluster of `workers` processes of one thread each, on the loopback address, with
    no dashboard, scheduled as docs/benchmark.md asks of any cluster: a worker is sent one run at
    a time (worker-saturation 1.0), so that a worker's death blames the run it was making only, and
    a run whose worker dies twice is given up (allowed-failures 1)."""
    import dask
    import distributed
    import logging
    with dask.config.set(SCHEDULER_CONFIG), _sigint_ignored():
        return distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                        dashboard_address=None, silence_logs=logging.ERROR)


@contextlib.contextmanager
def _sigint_ignored():
    """SIGINT ignored while the cluster's processes start, so that they inherit it ignored: Ctrl-C
    reaches the whole process group, and the client alone should answer it (cancelling the runs,
    writing those made, closing the cluster) rather than every worker printing its traceback."""
    try:
        previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # not the main thread: signals are not this thread's to set
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def started_at():
    """Now, as OMPL's logs say it: "2026-12-05T19:55:02" (local time)."""
    return time.strftime("%Y-%m-%dT%H:%M:%S")


def host():
    return socket.gethostname() or "UNKNOWN"


def client_threads(client):
    """The worker threads a Dask client's cluster has now."""
    return sum(w.get("nthreads", 1) for w in client.scheduler_info().get("workers", {}).values()) or 1


def _record_of(future, task):
    """The run's record, or a failed run's saying why the task gave none."""
    try:
        return future.result()
    except concurrent.futures.CancelledError:
        raise KeyboardInterrupt from None  # only Ctrl-C's cancelling, or the client's closing, gets here
    except Exception as e:  # noqa: BLE001 (any task failure becomes the run's record, never a lost run)
        if type(e).__name__ == "KilledWorker":
            why = ("the run failed: its worker died each time the run was tried (Dask: KilledWorker); the "
                   "planner crashed or exhausted the worker's memory")
        else:
            why = f"the run failed: its task raised {type(e).__name__} on its worker: {e}"
        return _polyplan._failed_record(task["problem"], task["entry"], task["seed"], why)


def _problem_files(problem, file):
    """A problem file's text, and the WKT file a world names ({its name as written: text})."""
    try:
        with open(file, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"problem {problem}: {file}: cannot be read: {e}") from None
    attachments = {}
    try:
        named = _json.loads(text).get("obstacles_wkt")
    except (ValueError, AttributeError):
        named = None  # the experiment's reader has read it: not JSON here means nothing attached
    if isinstance(named, str):
        if os.path.isabs(named) or ".." in named.replace("\\", "/").split("/"):
            raise InputError(f"problem {problem}: {file}: obstacles_wkt {_shown(named)}: a task carries the files "
                             "beside its world or below it; give the WKT file's path relative to the world, "
                             "without '..'")
        try:
            with open(os.path.join(os.path.dirname(file), named), encoding="utf-8") as f:
                attachments[named] = f.read()
        except (OSError, UnicodeDecodeError) as e:
            raise InputError(f"problem {problem}: {file}: obstacles_wkt {_shown(named)}: cannot be read: {e}") from None
    return text, attachments


def _attached(task):
    """A worker's folder holding the task's attached files as its problem names them; the problem's
    source, as if in that folder. One folder per content, written once."""
    digest = hashlib.sha256(_json.dumps([task["text"], task["attachments"]], sort_keys=True).encode()).hexdigest()
    folder = os.path.join(tempfile.gettempdir(), "polyplan-task-" + digest[:20])
    for name, text in task["attachments"].items():
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            os.makedirs(os.path.dirname(path), exist_ok=True)
            partial = f"{path}.{os.getpid()}.{uuid.uuid4().hex}"
            with open(partial, "w", encoding="utf-8") as f:
                f.write(text)
            os.replace(partial, path)  # whole or not at all, for the worker's other threads
    return os.path.join(folder, os.path.basename(task["source"]))


class _Pool:
    """Dask's client or a pool of threads, behind submit, as_completed and cancel."""

    def __init__(self, client, threads):
        self.client = client
        self.threads = None if client is not None else concurrent.futures.ThreadPoolExecutor(max(1, threads))

    def submit(self, task, tasks):
        """{future: its task}"""
        if self.client is None:
            return {self.threads.submit(task, t): t for t in tasks}
        run = uuid.uuid4().hex[:12]
        keys = [f"polyplan-run-{run}-{i}" for i in range(len(tasks))]
        futures = self.client.map(task, tasks, key=keys, pure=False, retries=0)
        return dict(zip(futures, tasks))

    def as_completed(self, futures):
        if self.client is None:
            return concurrent.futures.as_completed(futures)
        import distributed
        return distributed.as_completed(list(futures))

    def cancel(self, futures):
        if self.client is None:
            for future in futures:
                future.cancel()
        else:
            self.client.cancel(list(futures))

    def close(self):
        if self.threads is not None:
            self.threads.shutdown(wait=False, cancel_futures=True)


class _RecordLog:
    """The records gathered, with where each came from, and the results folder's runs.jsonl: its
    header (the experiment asked) and a line per record, flushed as it comes."""

    def __init__(self, spec, folder, resume):
        self.records, self.made, self.file = [], set(), None
        if folder is None:
            return
        path = os.path.join(folder, RECORDS)
        header = _json.dumps({"polyplan_runs": 1, "experiment": _comparable(spec.json())})
        if resume:
            self._read(spec, path, header)
        os.makedirs(folder, exist_ok=True)
        try:
            self.file = open(path, "a" if resume else "w", encoding="utf-8")
            if not resume:
                self.file.write(header + "\n")
                self.file.flush()
        except OSError as e:
            raise InputError(f"{path}: cannot be written: {e.strerror}") from None

    def add(self, record):
        self.records.append((record, "a run's record"))
        if self.file is not None:
            self.file.write(record + "\n")
            self.file.flush()

    def close(self):
        if self.file is not None:
            self.file.close()

    def _read(self, spec, path, header):
        try:
            with open(path, encoding="utf-8") as f:
                lines = f.read().splitlines()
        except OSError as e:
            raise InputError(f"{path}: cannot resume from it: {e.strerror} (the folder of an experiment run with "
                             "polyplan.Experiment.run(client=...) or python3 -m polyplan benchmark)") from None
        if not lines or lines[0] != header:
            raise InputError(f"{path}: written for {_asked(lines[0] if lines else '')}, not for this experiment "
                             f"({_asked(header)}): resume with the experiment, seeds and time limit it was run with")
        for number, line in enumerate(lines[1:], start=2):
            if not line.strip():
                continue
            where = f"{path}: line {number}"
            _polyplan._experiment_outcome(spec, [(line, where)], 0.0, 1, "", "")  # checks it, naming the line
            self.records.append((line, where))
            record = _json.loads(line)
            self.made.add((record["problem"], record["planner"], record["seed"]))


def _comparable(experiment):
    """What a resumed run must ask as the first did: the experiment without its files' paths
    (a folder may be resumed from another working folder)."""
    experiment = dict(experiment)
    experiment.pop("file", None)
    experiment["problems"] = [{k: v for k, v in p.items() if k != "file"} for p in experiment["problems"]]
    return experiment


def _asked(header):
    try:
        e = _json.loads(header)["experiment"]
        return (f"experiment {e['name']!r} ({len(e['problems'])} problems x {len(e['planners'])} planner entries x "
                f"{len(e['seeds'])} seeds, {e['time_limit']:g} s)")
    except (ValueError, KeyError, TypeError):
        return "something else (not a runs.jsonl header)"


class _Tally:
    """Runs made, solved and failed, for the progress line (or the caller's progress(done, total))."""

    def __init__(self, total, made, progress):
        self.total, self.progress = total, progress
        self.done = self.solved = self.failed = 0
        for text, _ in made:
            self.count(_json.loads(text))
        self.before = self.done  # made by an earlier run: not counted in this run's pace

    def count(self, record):
        self.done += 1
        self.solved += record["solved"]
        self.failed += record["why_not"].startswith(FAILED)

    def add(self, text):
        self.count(_json.loads(text))
        if self.progress is None:
            return
        if hasattr(self.progress, "tally"):
            self.progress.tally(self.done, self.total, self.solved, self.failed, self.before)
        else:
            self.progress(self.done, self.total)


def benchmark_command(args):
    """python3 -m polyplan benchmark: see usage()."""
    from .experiment import Experiment
    parser = argparse.ArgumentParser(
        prog="python3 -m polyplan benchmark",
        description="Run an experiment (problems x planner entries x seeds) on this machine's threads or on a Dask "
                    "cluster, one task per run, and write OMPL's benchmark log, results.json, results.csv, tables "
                    "and plots into DIR (docs/benchmark.md).")
    parser.add_argument("experiment", help="experiment file (JSON)")
    parser.add_argument("--out", help="folder for the results (default: NAME_results, NAME the experiment's)")
    parser.add_argument("--resume", metavar="DIR", help="make only the runs missing from DIR (an interrupted run's "
                        "--out) and write the whole results there")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="a running Dask scheduler to send the runs to")
    where.add_argument("--local-cluster", metavar="N", type=int, help="start a Dask cluster of N worker processes "
                       "on this machine (loopback only) and run on it")
    where.add_argument("--threads", type=_whole_in(0, 256), default=1, help="runs at a time on this machine "
                       "(default 1; 0: one per core), without Dask")
    parser.add_argument("--seeds", type=_whole_in(1, None), help="only the experiment's first N seeds")
    parser.add_argument("--time-limit", type=_seconds, help="seconds per run instead of the experiment's")
    options = parser.parse_args(args)
    if options.out and options.resume and os.path.abspath(options.out) != os.path.abspath(options.resume):
        parser.error("--out and --resume name different folders: the resumed results are written where they are")
    try:
        experiment = Experiment.from_file(options.experiment)
        if options.seeds is not None and options.seeds > len(experiment._spec.seeds):
            raise InputError(f"--seeds {options.seeds}: the experiment has {len(experiment._spec.seeds)} seeds")
        return _benchmark(experiment, options)
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2


def _whole_in(least, most):
    def whole(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r}: expected a whole number") from None
        if value < least or most is not None and value > most:
            raise argparse.ArgumentTypeError(f"{value}: expected a whole number in [{least}, {most or 'inf'}]")
        return value
    return whole


def _seconds(text):
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (value > 0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"{text!r}: expected a finite number of seconds > 0")
    return value


def _benchmark(experiment, options):
    out = options.resume or options.out or _polyplan._file_name_part(experiment.name) + "_results"
    if os.path.exists(out) and not os.path.isdir(out):
        raise InputError(f"{'--resume' if options.resume else '--out'} {out}: not a folder")
    cluster = client = None
    try:
        if options.local_cluster is not None or options.scheduler:
            client, cluster = _client(options)
        results = experiment.run(client=client, threads=options.threads, seeds=options.seeds,
                                 time_limit=options.time_limit, out=out, resume=bool(options.resume))
        code = 0
    except ExperimentInterrupted as stopped:
        results, code = stopped.results, 130
        print(f"interrupted: {len(results)} of {results.experiment_runs} runs made, written to {out}; "
              f"--resume {out} makes the rest", file=sys.stderr)
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    solved = sum(r["solved"] for r in results.records)
    print(f"{experiment.name}: {len(results)} runs, {solved} solved, {results.total_seconds:g} s")
    for path in results.written:
        print(f"wrote {path}")
    return code


def _client(options):
    if options.local_cluster is not None and not 1 <= options.local_cluster <= 256:
        raise InputError(f"--local-cluster {options.local_cluster}: expected 1 to 256 workers")
    try:
        import distributed
    except ImportError:
        raise InputError("--scheduler and --local-cluster need Dask's distributed (Debian: python3-distributed)") \
            from None
    if options.local_cluster is not None:
        cluster = local_cluster(options.local_cluster)
        return distributed.Client(cluster), cluster
    try:
        return distributed.Client(options.scheduler, timeout=30), None
    except (OSError, TimeoutError) as e:
        raise InputError(f"--scheduler {options.scheduler}: cannot connect: {e}") from None
