"""Planning releases the GIL: Python runs while a plan is made, and two threads planning on two
worlds plan at the same time. The proof is the overlap of the two calls, not a speed-up: a planner
holding the GIL lets the second call begin only when the first has returned, however idle the
machine, while a speed-up depends on how busy the machine is (a loaded CI runner gave 1.14 on two
cores). The speed-up is printed for a reader; performance claims live in bench/."""
import threading
import time

import pytest

import polyplan
from conftest import data

# About a second of work per plan: RRT* on the office world with a fixed number of iterations.
WORK = dict(seed=7, iterations=60000, time=120)


def work(world):
    return polyplan.planner("rrtstar", world, **WORK).plan(record=False)


def worlds():
    return [polyplan.read_world(data("worlds", "office.json")) for _ in range(2)]


def test_python_runs_while_a_plan_is_made():
    world = worlds()[0]
    polyplan.cspace(world)  # built first, so that the thread below only plans
    done = threading.Event()
    counted = [0]

    def plan():
        work(world)
        done.set()

    thread = threading.Thread(target=plan)
    began = time.perf_counter()
    thread.start()
    while not done.is_set():
        counted[0] += 1
        time.sleep(0.001)
    thread.join()
    elapsed = time.perf_counter() - began
    # With the GIL held for the whole plan, the loop would run once or twice.
    assert elapsed > 0.2, "the plan is too quick to show anything"
    assert counted[0] > 50, counted[0]


def test_two_threads_on_two_worlds_plan_at_the_same_time():
    first, second = worlds()
    for w in (first, second):
        polyplan.cspace(w)
    began = time.perf_counter()
    alone = [work(first), work(second)]
    sequential = time.perf_counter() - began

    results = [None, None]
    spans = [None, None]

    def plan(i, world):
        entered = time.perf_counter()
        results[i] = work(world)
        spans[i] = (entered, time.perf_counter())

    threads = [threading.Thread(target=plan, args=(i, w)) for i, w in enumerate((first, second))]
    began = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    parallel = time.perf_counter() - began
    print(f"two plans: {sequential:.2f} s one after the other, {parallel:.2f} s in two threads: "
          f"speed-up {sequential / parallel:.2f}")
    # The same answers (one seed, one path) ...
    assert [(r.status, r.length) for r in results] == [(r.status, r.length) for r in alone]
    # ... from two calls that ran at once: with the GIL held, the later call could only begin
    # once the earlier one had returned, and the overlap would be nil.
    overlap = min(end for _, end in spans) - max(entered for entered, _ in spans)
    shorter = min(end - entered for entered, end in spans)
    assert shorter > 0.2, "the plans are too quick to show anything"
    assert overlap > 0.5 * shorter, f"the calls overlapped {overlap:.2f} s of {shorter:.2f} s"


def test_one_world_from_two_threads_takes_turns_and_stays_right():
    world = worlds()[0]
    planner = polyplan.planner("visibility", world)
    expected = planner.plan().length
    lengths = []

    def plan():
        for _ in range(20):
            lengths.append(planner.plan().length)

    threads = [threading.Thread(target=plan) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert lengths == [expected] * 80
