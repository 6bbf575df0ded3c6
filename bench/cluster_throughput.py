"""The throughput of an experiment on a Dask LocalCluster of 1 and of 2 workers, side by side in one
run, against this machine's threads without Dask; and what a task costs beyond its run
(scheduling, serialisation, the record's way back), so that a user can size tasks.

    PYTHONPATH=build/python /usr/bin/python3 bench/cluster_throughput.py [--seeds N] [--time-limit S]

Two experiments: data/experiments/seed003_rrt_rrtstar.json cut to its first seeds and a short time
limit (the RRT* entries run to the limit, the RRT ones stop at their first solution), for the
throughput; and 200 quick runs (RRT-Connect on office.json, about a millisecond each), for the
overhead: (wall clock x workers - the runs' own setup and query seconds) / runs, on one worker.
"""
import argparse
import os
import sys
import time

import distributed

import polyplan
from polyplan import cluster

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data")


def run_seconds(results):
    return sum(r["time"] + r["setup_time"] for r in results.records)


def on_cluster(experiment, workers, **scale):
    with cluster.local_cluster(workers) as local, distributed.Client(local) as client:
        client.run(lambda: __import__("polyplan"))  # the module loaded before the clock starts
        started = time.monotonic()
        results = experiment.run(client=client, progress=False, **scale)
        return time.monotonic() - started, results


def on_threads(experiment, threads, **scale):
    started = time.monotonic()
    results = experiment.run(threads=threads, progress=False, **scale)
    return time.monotonic() - started, results


def throughput(seeds, time_limit):
    experiment = polyplan.Experiment.from_file(os.path.join(DATA, "experiments", "seed003_rrt_rrtstar.json"))
    scale = dict(seeds=seeds, time_limit=time_limit)
    rows = [("threads", 1, *on_threads(experiment, 1, **scale)), ("threads", 2, *on_threads(experiment, 2, **scale)),
            ("dask", 1, *on_cluster(experiment, 1, **scale)), ("dask", 2, *on_cluster(experiment, 2, **scale))]
    print(f"seed003_rrt_rrtstar, {seeds} seeds, {time_limit:g} s per run: {len(rows[0][3])} runs")
    print(f"{'engine':8} {'workers':>7} {'wall s':>8} {'runs/s':>8} {'busy':>6}")
    for engine, workers, wall, results in rows:
        busy = run_seconds(results) / (wall * workers)
        print(f"{engine:8} {workers:7d} {wall:8.2f} {len(results) / wall:8.2f} {busy:6.0%}")
    print(f"2 workers / 1 worker (dask): {rows[2][2] / rows[3][2]:.2f}x; "
          f"2 threads / 1 thread: {rows[0][2] / rows[1][2]:.2f}x")


def overhead(runs):
    experiment = polyplan.Experiment({
        "name": "quick", "problems": [{"name": "office", "file": os.path.join(DATA, "worlds", "office.json")}],
        "planners": [{"name": "rrtconnect", "planner": "rrtconnect"}],
        "seeds": list(range(1, runs + 1)), "time_limit": 10})
    for engine, measure in (("threads", on_threads), ("dask", on_cluster)):
        wall, results = measure(experiment, 1)
        own = run_seconds(results) / len(results)
        extra = (wall - run_seconds(results)) / len(results)
        print(f"{engine:8} {len(results)} quick runs on 1 worker: {wall:.2f} s, a run's own {own * 1e3:.2f} ms, "
              f"beyond it {extra * 1e3:.2f} ms per task")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--time-limit", type=float, default=0.25)
    parser.add_argument("--quick-runs", type=int, default=200)
    options = parser.parse_args()
    print(f"{os.cpu_count()} cores, polyplan from {os.path.dirname(polyplan.__file__)}, "
          f"distributed {distributed.__version__}")
    throughput(options.seeds, options.time_limit)
    overhead(options.quick_runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
