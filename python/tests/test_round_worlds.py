"""Worlds with discs, walls, disc bounds and a disc robot from Python: read exactly, their paths
checked exactly (grazing a disc is valid, crossing a wall at a point is not), drawn with their
circles and walls, and refused by the planners that do not plan with them, naming what the world
has — never planned straight through."""
from fractions import Fraction

import numpy as np
import pytest

import polyplan
from conftest import data


def test_a_wall_may_be_passed_round_its_end_but_not_crossed():
    world = polyplan.read_world(data("worlds", "walls_bug.json"))
    valid, why = polyplan.check(world, np.array([[-3, 0.5], [0, 100], [2, 0]]))  # round its end
    assert valid, why
    valid, why = polyplan.check(world, np.array([[-3, 0.5], [2, 0]]))
    assert not valid and "crosses a wall" in why


def test_a_path_may_graze_a_disc():
    # The line y = 0.3 touches the disc of centre (0, 0.1) and radius 0.2: in doubles it enters it.
    world = polyplan.World.from_dict({"discs": [{"center": [0, "0.1"], "radius": "0.2"}]})
    assert polyplan.check(world, [["-1", "0.3"], ["1", "0.3"]]) == (True, "")
    assert not polyplan.check(world, [["-1", "0.2999999999"], ["1", "0.2999999999"]])[0]


def test_planners_refuse_them_naming_what_the_world_has():
    world = polyplan.read_world(data("worlds", "disc_robot_floor_plan.json"))
    with pytest.raises(polyplan.InputError, match=r"disc_robot_floor_plan.json: discs, walls, a disc robot: "
                                                   r"the planner trapezoid plans polygon worlds only.*use one that plans "
                                                   r"with them \(visibility, prm, lazyprm, rrt, rrtstar, rrtconnect, "
                                                   r"raster, gvd-grid, dstar-lite, lpastar, repeated-astar, "
                                                   r"navigation-function, potential-field, bug1, bug2, tangent-bug\)"):
        polyplan.plan(world, planner="trapezoid")


def test_the_sampling_planners_plan_them_and_the_checker_agrees():
    world = polyplan.read_world(data("worlds", "sphere_world.json"))
    plans = polyplan.plan(world, planner="rrt", seed=2)
    assert len(plans) == 10 and all(p.status == "solved" for p in plans)
    for p in plans:
        assert polyplan.check(world, p) == (True, "")  # the plan's exact path, checked afresh
    floor = polyplan.read_world(data("worlds", "disc_robot_floor_plan.json"))
    plan = polyplan.plan(floor, planner="rrtconnect", seed=1)[0]
    assert plan.status == "solved"
    assert polyplan.check(floor, plan) == (True, "")
    assert "walls (zero thickness)" in polyplan.svg(floor, plan)


def test_the_default_plans_the_shortest_path_of_tangents_and_arcs():
    # Round one disc of radius 1 from 3 away on each side: two tangents of √8 and the arc between.
    world = polyplan.World.from_dict({"bounds": [-10, -10, 10, 10], "discs": [{"center": [0, 0], "radius": 1}],
                                      "start": [-3, 0], "goal": [3, 0]})
    plan = polyplan.plan(world)[0]
    expected = 2 * np.sqrt(8) + np.pi - 2 * np.arccos(1 / 3)
    assert plan.planner == "visibility" and plan.status == "solved"
    assert abs(plan.length - expected) <= 1e-12 * expected
    assert plan.facts["length_lower"] <= expected <= plan.facts["length_upper"]
    assert [p["kind"] for p in plan.pieces] == ["segment", "arc", "segment"]
    arc = plan.pieces[1]
    assert arc["centre"] == [0, 0] and arc["radius"] == 1 and arc["turn"] in ("ccw", "cw")
    assert plan.path.shape == (4, 2) and plan.path_exact is None  # the touching points are irrational
    assert "path" in polyplan.svg(world, plan)


def test_the_picture_shows_the_discs_and_walls():
    picture = polyplan.svg(polyplan.read_world(data("worlds", "disc_robot_floor_plan.json")))
    for legend in ("obstacles and discs", "walls (zero thickness)", "robot at start", "bounds"):
        assert legend in picture, legend


def test_an_unknown_field_that_may_hold_obstacles_is_refused():
    with pytest.raises(polyplan.InputError, match=r'unknown field "circles": it may describe what is not free'):
        polyplan.World.from_dict({"obstacles": [], "circles": [{"center": [0, 0], "radius": 1}]})


def test_the_program_checks_a_path_among_walls(tmp_path):
    from conftest import run_cli
    path = tmp_path / "through.json"
    path.write_text('{"path": [[1, 1], [11, 7]]}')
    code, out, err = run_cli("check", data("worlds", "disc_robot_floor_plan.json"), str(path))
    assert code == 1 and "walls[" in out + err, (out, err)
    path.write_text('{"path": [[1, 1], [3.5, 3.5], [5, 3.5], [7, 4.5], [10.5, 4.5], [11, 7]]}')
    code, out, err = run_cli("check", data("worlds", "disc_robot_floor_plan.json"), str(path))
    assert code == 0, (out, err)


def test_a_polygon_robot_among_discs_and_walls():
    # A 2×2 square round a unit disc: its C-obstacle is the square [-1, 1]² rounded by 1, and the
    # shortest way over it is 10 + 4·atan(1/4) (tangents of 4, two arcs, the top side of 2).
    world = polyplan.World.from_dict({"bounds": [-10, -10, 10, 10],
                                      "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]},
                                      "discs": [{"center": [0, 0], "radius": 1}], "start": [-5, 0], "goal": [5, 0]})
    plan = polyplan.plan(world)[0]
    expected = 10 + 4 * np.arctan(0.25)
    assert plan.status == "solved" and abs(plan.length - expected) <= 1e-12 * expected
    assert [p["kind"] for p in plan.pieces] == ["segment", "arc", "segment", "arc", "segment"]
    # The rectangle lies flat through the floor plan's doorways; no straight line through a wall.
    floor = polyplan.read_world(data("worlds", "polygon_robot_floor_plan.json"))
    plan = polyplan.plan(floor, planner="rrtconnect", seed=1)[0]
    assert plan.status == "solved" and polyplan.check(floor, plan) == (True, "")
    valid, why = polyplan.check(floor, np.array([[1, 1], [11, 7]]))
    assert not valid and "walls[" in why, why


def test_dstar_lite_drives_the_sphere_world_and_the_checker_agrees():
    # Every query driven on the raster of the discs, each path checked afresh among them; repeated
    # A* on the same raster drives the same grid cost.
    world = polyplan.read_world(data("worlds", "sphere_world.json"))
    plans = polyplan.plan(world, planner="dstar-lite")
    assert len(plans) == 10 and all(p.status == "solved" for p in plans)
    for p in plans:
        assert polyplan.check(world, p) == (True, "")
        assert p.facts["replan"]["algorithm"] == "dstar-lite"
    again = polyplan.plan(world, planner="repeated-astar")
    assert [p.facts["replan"]["grid_cost"] for p in plans] == [p.facts["replan"]["grid_cost"] for p in again]


def test_the_world_and_its_plot_show_discs_walls_and_arcs():
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.patches import Circle
    floor = polyplan.read_world(data("worlds", "disc_robot_floor_plan.json"))
    assert floor.discs.tolist() == [[2, 6, 0.8]] and len(floor.walls) == 5 and floor.walls[4].tolist() == [[8, 5], [10, 5]]
    assert floor.robot_disc == Fraction(3, 10) and floor.disc_bounds is None and floor.robot == []
    assert "discs, walls, disc robot of radius 3/10" in repr(floor)
    sphere = polyplan.read_world(data("worlds", "sphere_world_disc_bounds.json"))
    assert sphere.disc_bounds == (0, 0, 10) and sphere.bounds is None
    plan = polyplan.plan(floor)[0]
    ax = polyplan.plot(plan)
    circles = [(tuple(map(float, p.center)), round(p.radius, 12)) for p in ax.patches if isinstance(p, Circle)]
    assert ((2, 6), 0.8) in circles and ((2, 6), 1.1) in circles  # the table, and its C-obstacle grown by 0.3
    assert ((4, 3), 0.3) in circles  # a wall's end grown by the robot's radius
    from polyplan.plotting import drawn_path
    drawn = drawn_path(plan, floor)
    assert len(drawn) > len(plan.pieces) + 1  # the arcs drawn through their points
    assert np.allclose(drawn[0], [1, 1]) and np.allclose(drawn[-1], [11, 7])
    for piece in plan.pieces:  # every drawn point on an arc lies on its circle
        if piece["kind"] == "arc":
            on = np.abs(np.hypot(*(drawn - piece["centre"]).T) - piece["radius"]) < 1e-9
            assert on.sum() >= 2


def test_the_bugs_follow_arcs():
    # Round the unit disc from (-3, 0) to (3, 0): Bug2 over the top, 2 + π + 2; Bug1 once round first.
    world = polyplan.World.from_dict({"discs": [{"center": [0, 0], "radius": 1}], "start": [-3, 0],
                                      "goal": [3, 0]})
    two = polyplan.plan(world, planner="bug2")[0]
    assert two.status == "solved"
    assert [p["kind"] for p in two.pieces] == ["segment", "arc", "segment"]
    assert abs(two.length - (4 + np.pi)) <= 1e-12 * two.length
    assert np.array_equal(two.facts["bug"]["hits"], [[-1, 0]]) and np.array_equal(two.facts["bug"]["leaves"], [[1, 0]])
    one = polyplan.plan(world, planner="bug1")[0]
    assert abs(one.length - (4 + 3 * np.pi)) <= 1e-12 * one.length
