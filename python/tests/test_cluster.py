"""Experiment.run(client=...) and python3 -m polyplan benchmark on a Dask cluster: a LocalCluster
on the loopback address, started and stopped here. The runs are the local runs (every run that
stops by its own rule gives the same record on any worker); a worker killed by its pid loses no
run; a run that kills its worker twice is recorded as failed; Ctrl-C writes the runs made, marked
incomplete, and --resume makes the rest only."""
import json
import os
import signal
import subprocess
import sys
import time

import pytest

import polyplan
from conftest import clockless, data
from polyplan import cluster

try:
    import distributed
except ImportError:
    distributed = None
# Each test skips rather than the module, so that pytest still collects them and exits 0.
pytestmark = [
    pytest.mark.skipif(distributed is None, reason="Dask's distributed is not installed (Debian: "
                       "python3-distributed; scripts/setup.sh python installs it)"),
    pytest.mark.skipif("asan" in os.environ.get("LD_PRELOAD", ""),
                       reason="a sanitized tree: each worker process would load the sanitizer's runtime, slowly, "
                              "and the runs' code is the one test_experiment runs sanitized"),
]

# Runs that stop by their own rule (a first solution, an iteration count), not by the clock, so
# that the same seed gives the same record on any worker; the WKT world's obstacles come from a
# file its world names, which a task carries.
SPEC = {
    "name": "cluster",
    "problems": [{"name": "office", "file": data("worlds", "office.json")},
                 {"name": "wkt", "file": data("worlds", "wkt_obstacles.json")},
                 {"name": "3R", "file": data("arms", "three_link_forest.json")}],
    "planners": [{"name": "rrt", "planner": "rrt", "options": {"goal-bias": 0.2}},
                 {"name": "rrtstar-600", "planner": "rrtstar", "options": {"iterations": 600}}],
    "seeds": [1, 2, 3],
    "time_limit": 100,
}
RUNS = 3 * 2 * 3
# Slow enough runs (about 0.2 s each) that a worker is killed, or Ctrl-C comes, in the middle of one.
SLOW = dict(SPEC, name="slow", problems=SPEC["problems"][:1], seeds=list(range(1, 9)),
            planners=[{"name": "rrtstar-slow", "planner": "rrtstar", "options": {"iterations": 20000}}])


@pytest.fixture(scope="module")
def client():
    local = cluster.local_cluster(2)
    with distributed.Client(local) as c:
        yield c
    local.close()


@pytest.fixture(scope="module")
def local_results():
    return polyplan.Experiment(SPEC).run(threads=2, progress=False)


def test_cluster_runs_are_the_local_runs(client, local_results, tmp_path):
    results = polyplan.Experiment(SPEC).run(client=client, progress=False, out=tmp_path)
    assert results.complete and len(results) == RUNS and results.threads == 2
    assert [clockless(r) for r in results.records] == [clockless(r) for r in local_results.records]
    assert sum(r["solved"] for r in results.records) == sum(r["solved"] for r in local_results.records) > 0
    # The program's files, and every run's record as it came.
    names = sorted(os.listdir(tmp_path))
    assert {"results.log", "results.json", "results.csv", "tables.md", "runs.jsonl", "office-success.svg"} <= set(names)
    assert len((tmp_path / "runs.jsonl").read_text().splitlines()) == 1 + RUNS
    written = json.loads((tmp_path / "results.json").read_text())
    assert written["complete"] and written["missing_runs"] == 0
    assert "incomplete" not in (tmp_path / "results.log").read_text()


def test_a_killed_worker_loses_no_run(client, tmp_path):
    killed = []

    def kill_one_busy_worker(done, total):
        if killed or done < 2:
            return
        busy = [address for address, keys in client.processing().items() if keys]
        pids = client.run(os.getpid, workers=busy[:1])
        for address, pid in pids.items():
            os.kill(pid, signal.SIGKILL)
            killed.append(address)

    results = polyplan.Experiment(SLOW).run(client=client, progress=kill_one_busy_worker, out=tmp_path)
    assert killed, "no worker was busy to be killed"
    assert results.complete and len(results) == 8
    assert not [r for r in results.records if r.get("why_not", "").startswith(cluster.FAILED)]
    local = polyplan.Experiment(SLOW).run(threads=1, progress=False)
    assert [clockless(r) for r in results.records] == [clockless(r) for r in local.records]
    client.wait_for_workers(2, timeout=60)  # the nanny restarts it, for the tests that follow


def test_a_run_stopped_by_its_time_limit_is_recorded_as_such(client):
    spec = dict(SPEC, problems=[{"name": "maze", "file": data("worlds", "maze.json")}], time_limit=0.002,
                planners=[{"name": "rrt", "planner": "rrt", "options": {"iterations": 100000000}}])
    results = polyplan.Experiment(spec).run(client=client, progress=False)
    assert results.complete and len(results) == 3
    for record in results.records:
        assert record["status"] == "limit" and not record["solved"], record
        assert record["facts"]["stopped_by"] == "time limit" and "time limit (0.002 s)" in record["why_not"]


def crash_on_seed_2(task):
    """A task that kills its worker process, as a crashing planner would, for seed 2."""
    if task["seed"] == 2:
        os._exit(3)
    return cluster.run_task(task)


def test_a_run_that_kills_its_worker_twice_is_recorded_failed(client):
    import cloudpickle
    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # the workers cannot import this file
    spec = polyplan.Experiment(dict(SPEC, problems=SPEC["problems"][:1], planners=SPEC["planners"][:1]))._spec
    records, _, interrupted = cluster.gather(spec, cluster.tasks_of(spec), client=client, task=crash_on_seed_2)
    assert not interrupted and len(records) == 3
    runs = [json.loads(text) for text, _ in records]
    failed = [r for r in runs if r["why_not"].startswith(cluster.FAILED)]
    assert [r["seed"] for r in failed] == [2]
    assert "KilledWorker" in failed[0]["why_not"] and failed[0]["status"] == "not_found"
    assert all(r["solved"] for r in runs if r["seed"] != 2)
    client.wait_for_workers(2, timeout=60)


def test_ctrl_c_keeps_the_runs_made_and_resume_makes_the_rest(client, local_results, tmp_path):
    calls = []

    def interrupt_after_four(done, total):
        calls.append(done)
        if done == 4:
            raise KeyboardInterrupt

    with pytest.raises(polyplan.ExperimentInterrupted) as stopped:
        polyplan.Experiment(SPEC).run(client=client, progress=interrupt_after_four, out=tmp_path)
    partial = stopped.value.results
    assert not partial.complete and len(partial) == 4 and partial.experiment_runs == RUNS
    written = json.loads((tmp_path / "results.json").read_text())
    assert not written["complete"] and written["missing_runs"] == RUNS - 4
    assert f"incomplete: {RUNS - 4} of {RUNS} runs missing" in (tmp_path / "results.log").read_text()
    assert "**Incomplete:**" in (tmp_path / "tables.md").read_text()

    calls.clear()
    results = polyplan.Experiment(SPEC).run(client=client, progress=lambda d, t: calls.append(d), out=tmp_path,
                                            resume=True)
    assert calls[0] == 5 and calls[-1] == RUNS and len(calls) == RUNS - 4  # the missing runs only
    assert results.complete
    assert [clockless(r) for r in results.records] == [clockless(r) for r in local_results.records]
    assert len((tmp_path / "runs.jsonl").read_text().splitlines()) == 1 + RUNS


def test_resume_refuses_another_experiment(client, tmp_path):
    polyplan.Experiment(SPEC).run(client=client, progress=False, out=tmp_path, seeds=1)
    with pytest.raises(polyplan.InputError, match=r"runs.jsonl: written for experiment 'cluster' .*1 seeds.*3 seeds"):
        polyplan.Experiment(SPEC).run(client=client, progress=False, out=tmp_path, resume=True)
    with pytest.raises(polyplan.InputError, match="resume: needs out"):
        polyplan.Experiment(SPEC).run(resume=True)
    with pytest.raises(polyplan.InputError, match="client: expected a dask.distributed.Client, got str"):
        polyplan.Experiment(SPEC).run(client="tcp://127.0.0.1:8786")
    with pytest.raises(polyplan.InputError, match=r"runs.jsonl: cannot resume from it"):
        polyplan.Experiment(SPEC).run(progress=False, out=tmp_path / "none", resume=True)
    (tmp_path / "runs.jsonl").write_text((tmp_path / "runs.jsonl").read_text().splitlines()[0] + "\n{\"problem\": 1}\n")
    with pytest.raises(polyplan.InputError, match=r"runs.jsonl: line 2: problem: expected text"):
        polyplan.Experiment(SPEC).run(client=client, progress=False, out=tmp_path, seeds=1, resume=True)


def module_command(*args):
    return [sys.executable, "-m", "polyplan", "benchmark", *args]


def test_the_shell_command_on_a_scheduler(client, tmp_path):
    experiment = tmp_path / "cluster.json"
    experiment.write_text(json.dumps(SPEC))
    address = client.scheduler.address
    done = subprocess.run(module_command(str(experiment), "--scheduler", address, "--out", str(tmp_path / "out")),
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert f"cluster: {RUNS} runs, " in done.stdout and "wrote " in done.stdout
    assert f"runs: {RUNS}/{RUNS}, " in done.stderr and " failed" in done.stderr
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    assert results["complete"] and len(results["runs"]) == RUNS
    refused = subprocess.run(module_command(str(experiment), "--scheduler", address, "--local-cluster", "2"),
                             capture_output=True, text=True, timeout=60)
    assert refused.returncode == 2 and "not allowed with argument" in refused.stderr


def test_ctrl_c_on_the_shell_command_and_resume(tmp_path):
    """Ctrl-C on python3 -m polyplan benchmark --local-cluster, then --resume on this machine's
    threads: the runs made are kept, the rest made once."""
    experiment = tmp_path / "slow.json"
    experiment.write_text(json.dumps(dict(SLOW, seeds=list(range(1, 17)))))
    out = tmp_path / "out"
    # Its own process group, to which Ctrl-C is sent as a terminal sends it: to the client and to
    # every process of its local cluster.
    running = subprocess.Popen(module_command(str(experiment), "--out", str(out), "--local-cluster", "2"),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    records = out / "runs.jsonl"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not (records.exists() and len(records.read_text().splitlines()) >= 3):
        time.sleep(0.05)
    os.killpg(running.pid, signal.SIGINT)
    stdout, stderr = running.communicate(timeout=120)
    assert running.returncode == 130, stderr
    assert f"--resume {out} makes the rest" in stderr
    assert "Traceback" not in stderr  # the workers leave Ctrl-C to the client
    made = len(records.read_text().splitlines()) - 1
    assert 2 <= made < 16
    assert not json.loads((out / "results.json").read_text())["complete"]

    resumed = subprocess.run(module_command(str(experiment), "--resume", str(out), "--threads", "2"),
                             capture_output=True, text=True, timeout=300)
    assert resumed.returncode == 0, resumed.stderr
    results = json.loads((out / "results.json").read_text())
    assert results["complete"] and len(results["runs"]) == 16
    assert sorted(r["seed"] for r in results["runs"]) == list(range(1, 17))
    assert "slow: 16 runs, 16 solved" in resumed.stdout  # the whole results, not the resumed part alone
