"""The surface scripts rely on, as the issue names it, used the way a notebook uses it."""
import json
from decimal import Decimal
from fractions import Fraction

import matplotlib
import numpy as np
import pytest

import polyplan
from conftest import data

matplotlib.use("Agg")


def test_the_documented_session():
    w = polyplan.read_world(data("worlds", "seed004.json"))
    infos = polyplan.planners()
    assert {"visibility", "rrtconnect", "rotation", "grid"} <= {i.name for i in infos}
    p = polyplan.planner("visibility", w, search="astar")
    r = p.plan(start=(5, 5), goal=(95, 80))
    assert r.found and r.status == "solved" and r.why_not is None and r.length > 0
    assert r.path.shape[1] == 2 and r.path.dtype == np.float64
    assert tuple(r.path[0]) == (5, 5) and tuple(r.path[-1]) == (95, 80)
    assert r.path_exact[0] == (Fraction(5), Fraction(5))
    # (2, 3) is too near the boundary for the course's C-space and visibility-graph problem set's robot: an answer, not an error.
    assert p.plan(start=(2, 3), goal=(95, 80)).status == "invalid_query"
    assert r.facts["search"]["expanded"] > 0 and r.facts["search"]["algorithm"] == "astar"
    assert json.loads(r.to_json())["length"] == r.length
    rs = polyplan.plan(w, planner="rrtconnect", seed=3)
    assert isinstance(rs, list) and len(rs) == len(w.queries) and all(x.found for x in rs)
    assert polyplan.check(w, r.path) == (True, "")
    assert polyplan.check(w, r.path_exact) == (True, "")
    cs = polyplan.cspace(w)
    assert all(isinstance(o, np.ndarray) and o.shape[1] == 2 for o in cs.obstacles)
    assert isinstance(cs.free_area, Fraction) and sum(c.area for c in cs.free_components) == cs.free_area
    a = polyplan.read_arm(data("arms", "four_link_forest.json"))
    plans = polyplan.plan(a, planner="grid", resolution=1)
    assert plans[0].found and plans[0].path.shape[1] == 4
    assert polyplan.svg(w, r).lstrip().startswith("<")
    assert "<svg" in polyplan.svg(w, r)
    ax = polyplan.plot(r)
    assert len(ax.lines) >= 1


def test_the_path_is_the_shortest():
    # the course's C-space and visibility-graph problem set's shortest path, the report's table: 5 segments, cost 118.94.
    w = polyplan.read_world(data("worlds", "seed004.json"))
    r = polyplan.plan(w, planner="visibility", search="dijkstra")[0]
    assert len(r.path) - 1 == 5 and round(r.length, 2) == 118.94
    assert r.length == pytest.approx(np.linalg.norm(np.diff(r.path, axis=0), axis=1).sum(), rel=1e-12)


def test_a_world_from_a_dict_is_the_world_from_its_file():
    path = data("worlds", "office.json")
    with open(path) as f:
        d = json.load(f, parse_float=Decimal)  # the file's decimals, exactly
    from_file, from_dict = polyplan.read_world(path), polyplan.World.from_dict(d, name=path)
    assert from_dict.queries == from_file.queries
    assert all(np.array_equal(a, b) for a, b in zip(from_dict.obstacles, from_file.obstacles))
    assert polyplan.cspace(from_dict).free_area == polyplan.cspace(from_file).free_area
    assert [r.length for r in polyplan.plan(from_dict)] == [r.length for r in polyplan.plan(from_file)]
    # json.load's floats are doubles: 0.1 is then 0.1000000000000000055..., and the area shows it.
    with open(path) as f:
        doubles = polyplan.World.from_dict(json.load(f))
    assert polyplan.cspace(doubles).free_area != polyplan.cspace(from_file).free_area


def test_an_arm_from_a_dict():
    with open(data("arms", "two_link_points.json")) as f:
        d = json.load(f)
    a = polyplan.Arm.from_dict(d)
    assert a.joints == 2 and a.links == [5, 5] and a.link_width == 0.5 and len(a.points) == 24
    tip = a.joint_positions([0, 0])
    assert tip.tolist() == [[0, 0], [5, 0], [10, 0]]
    assert polyplan.Arm.from_json(json.dumps(d)).queries == a.queries


def test_one_planner_answers_many_queries():
    w = polyplan.read_world(data("worlds", "seed004.json"))
    p = polyplan.planner("visibility", w)
    assert p.name == "visibility" and "translat" in p.space
    by_name = p.plan(query=w.queries[0][0])
    by_index = p.plan(query=0)
    default = p.plan()
    assert by_name.length == by_index.length == default.length
    assert p.plan(start=(10, 10), goal=(10, 10)).length == 0


def test_rotating_robot_poses():
    w = polyplan.read_world(data("worlds", "rotation_piano.json"))
    r = polyplan.plan(w, planner="rotation")[0]
    assert r.found and r.path.shape[1] == 3
    assert r.path_exact is not None and len(r.path_exact[0]) == 4
    assert "<svg" in polyplan.svg(w, [r])
    polyplan.plot(r)


def test_recorded_parts_for_pictures():
    w = polyplan.read_world(data("worlds", "sphere_world_polygons.json"))
    r = polyplan.planner("raster", w).plan()
    assert r.cells is not None and r.cells.states.dtype == np.uint8 and r.cells.states.ndim == 2
    assert (r.cells.states == 2).any() and (r.cells.states == 1).any()
    t = polyplan.planner("trapezoid", w).plan()
    assert t.decomposition and all(c.shape[1] == 2 for c in t.decomposition)
    v = polyplan.planner("visibility", w).plan(record=False)
    assert v.graph is None and len(v.expanded) == 0
    polyplan.plot([r])
    polyplan.plot(t)


def test_arm_pictures():
    a = polyplan.read_arm(data("arms", "two_link_points.json"))
    r = polyplan.plan(a)[0]
    assert r.problem is not None and isinstance(r.problem, polyplan.Arm)
    assert "<svg" in polyplan.svg(a, r) and "<svg" in polyplan.svg(a, r, strobe=True)
    assert r.cells is not None and r.cells.wraps
    polyplan.plot(r)


def test_reprs_say_what_they_are():
    w = polyplan.read_world(data("worlds", "seed004.json"))
    r = polyplan.plan(w)[0]
    assert "seed004" in repr(w) and "visibility" in repr(r) and "solved" in repr(r)
    assert "visibility" in repr(polyplan.planner("visibility", w))


def test_several_plans_each_in_its_colour_and_a_failed_one_with_its_ends_and_status():
    w = polyplan.read_world(data("worlds", "seed004.json"))
    plans = [polyplan.planner(name, w).plan() for name in ("visibility", "trapezoid", "voronoi")]
    ax = polyplan.plot(plans)
    paths = [line for line in ax.get_lines() if line.get_label().startswith(("visibility", "trapezoid", "voronoi"))]
    assert len(paths) == 3 and len({line.get_color() for line in paths}) == 3
    trap = polyplan.read_world(data("worlds", "u_trap.json"))
    failed = polyplan.plan(trap, planner="potential-field")[0]  # stuck in the trap: local_minimum
    assert not failed.found
    ax = polyplan.plot(failed)
    labels = [line.get_label() for line in ax.get_lines()]
    assert any(label.endswith(": " + failed.status) for label in labels), labels
    assert len([line for line in ax.get_lines() if line.get_marker() in ("o", "*")]) == 2
