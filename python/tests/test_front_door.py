"""The front door from Python: options spelt with underscores, point options as pairs, ranges
listed and enforced, the problem's default planner, and Plan.facts holding every key the JSON
has beside the answer (built from the JSON's tree, not its text)."""
import json
import math

import pytest

import polyplan
from conftest import data

ANSWER = {"query", "found", "status", "length", "path", "path_exact", "segments", "why_not", "certified",
          "certified_by"}


def same(a, b):
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return a == b


@pytest.mark.parametrize("problem,planner,options", [
    ("worlds/seed004.json", "visibility", {}),
    ("worlds/seed004.json", "voronoi", {}),                       # clearance and bottleneck
    ("worlds/tether_pillar.json", "homotopy", {"classes": 3}),    # further paths
    ("worlds/seed004.json", "rrt", {"goal_bias": 0.2, "iterations": 2000, "time": 100}),
    ("worlds/tether_pillar.json", "tether", {"tether_base": (0, 0)}),
    ("arms/two_link_points.json", "grid", {"memory_mb": 500, "exact_cells": 1000000}),
])
def test_facts_hold_every_key_of_the_json_beside_the_answer(problem, planner, options):
    reader = polyplan.read_arm if problem.startswith("arms") else polyplan.read_world
    for plan in polyplan.plan(reader(data(*problem.split("/"))), planner=planner, **options):
        j = json.loads(plan.to_json())
        expected = {k: v for k, v in j.items() if k not in ANSWER}
        assert set(plan.facts) == set(expected), (set(plan.facts) ^ set(expected))
        # Points, points and cells are arrays and tuples in Python, lists in the JSON.
        as_json = json.loads(json.dumps(plan.facts, default=lambda a: a.tolist()))
        assert same(as_json, expected)


def test_every_number_option_lists_its_range_and_an_enumeration_its_choices():
    for info in polyplan.planners():
        for o in info.options:
            if "number" in o.kind:
                assert o.range is not None, (info.name, o.name)
            if "|" in o.kind:
                assert o.choices, (info.name, o.name)
    rrt = next(o for p in polyplan.planners() if p.name == "rrt" for o in p.options if o.name == "goal-bias")
    assert rrt.range == (0.0, 1.0, False, False)


def test_an_out_of_range_value_is_refused_naming_the_option_value_and_range():
    world = polyplan.read_world(data("worlds", "seed004.json"))
    with pytest.raises(polyplan.InputError, match=r"option goal-bias=2: expected a number in \[0, 1\]"):
        polyplan.planner("rrt", world, goal_bias=2)
    with pytest.raises(polyplan.InputError, match="goal_bais: no such option"):
        polyplan.planner("rrt", world, goal_bais=0.1)
    with pytest.raises(polyplan.InputError, match="weight"):
        polyplan.planner("visibility", world, weight=[3])  # a sequence only for a point option


def test_the_problems_default_planner():
    assert polyplan.plan(polyplan.read_arm(data("arms", "two_link_points.json")))[0].planner == "grid"
    assert polyplan.plan(polyplan.read_world(data("worlds", "car_park.json")))[0].planner == "hybrid-astar"
    assert polyplan.plan(polyplan.read_world(data("worlds", "rotation_piano.json")))[0].planner == "rotation"
