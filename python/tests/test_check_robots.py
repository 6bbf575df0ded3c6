"""polyplan.check for every robot, each by its own motion model: a car's path as the arcs it
drove (its (N, 3) poses or its segments), a rotating robot's poses (translations and turns on the
spot), an arm's configurations (certified motions) — every planner's answer valid, and paths that
cut through obstacles, slide a car sideways or move and turn at once refused with the reason."""
import math

import numpy as np
import pytest

import polyplan
from conftest import data


def test_a_cars_path_is_checked_as_the_arcs_it_drove():
    world = polyplan.read_world(data("worlds", "car_parallel_parking.json"))
    plan = polyplan.plan(world)[0]
    assert plan.found and plan.path.shape[1] == 3
    assert polyplan.check(world, plan) == (True, "")
    assert polyplan.check(world, plan.path) == (True, "")  # the poses: the arcs between them found again
    assert polyplan.check(world, plan.segments) == (True, "")
    # The same points as a polyline of positions is not what the car drove: refused, not checked as one.
    with pytest.raises(polyplan.InputError, match=r"\(N, 3\) poses"):
        polyplan.check(world, plan.path[:, :2])
    # A car does not slide sideways: shift one pose across the heading.
    moved = plan.path.copy()
    heading = math.radians(moved[1, 2])
    moved[1, :2] += 0.5 * np.array([-math.sin(heading), math.cos(heading)])
    with pytest.raises(polyplan.InputError, match=r"path\[0\] to path\[1\]: no straight and no arc"):
        polyplan.check(world, moved)


def test_a_car_driving_into_an_obstacle_is_refused():
    world = polyplan.read_world(data("worlds", "car_slalom.json"))
    plan = polyplan.plan(world)[0]
    assert polyplan.check(world, plan.path) == (True, "")
    start = plan.path[0]
    # Straight ahead from the start, far: through the slalom's posts.
    x, y, theta = start
    far = [x + 100 * math.cos(math.radians(theta)), y + 100 * math.sin(math.radians(theta)), theta]
    valid, reason = polyplan.check(world, [start, far])
    assert not valid and "not proved free" in reason


def test_a_rotating_robots_path_is_checked_with_its_turns():
    world = polyplan.read_world(data("worlds", "rotation_piano.json"))
    plan = polyplan.plan(world, planner="rotation")[0]
    assert plan.found and plan.path.shape[1] == 3
    assert polyplan.check(world, plan) == (True, "")
    assert polyplan.check(world, plan.path_exact) == (True, "")  # (x, y, sin, cos), exactly
    # Its doubles round the corners it turns at, some into the obstacles it touches: checked as
    # given, exactly, so they may be refused; never accepted through an obstacle.
    valid, reason = polyplan.check(world, plan.path)
    assert valid or "obstacles[" in reason
    # Moving and turning in one step is not a motion of the planner.
    both = plan.path[[0, -1]]
    assert not np.allclose(both[0, :2], both[1, :2]) and both[0, 2] != both[1, 2]
    valid, reason = polyplan.check(world, both)
    assert not valid and "moves and turns at once" in reason


def test_a_turn_on_the_spot_that_sweeps_an_obstacle_is_refused():
    world = polyplan.World.from_dict({
        "bounds": [-10, -10, 10, 10],
        "robot": {"parts": [[[-3, -0.5], [3, -0.5], [3, 0.5], [-3, 0.5]]]},
        "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})
    assert polyplan.check(world, [[0, 0, 0], [5, 0, 0]]) == (True, "")  # below the block, level
    valid, reason = polyplan.check(world, [[0, 0, 0], [0, 0, 90]])  # the bar sweeps through the block
    assert not valid and "turn on the spot" in reason
    assert polyplan.check(world, [[-6, 0, 0], [-6, 0, 90]]) == (True, "")  # far from it
    with pytest.raises(polyplan.InputError, match="not an exact rotation"):
        polyplan.check(world, [[0, 0, "1/2", "1/2"]])


def test_an_arms_path_is_checked_as_certified_motions():
    arm = polyplan.read_arm(data("arms", "two_link_points.json"))
    plan = polyplan.plan(arm, planner="grid")[0]
    assert plan.found
    assert polyplan.check(arm, plan) == (True, "")
    assert polyplan.check(arm, plan.path) == (True, "")
    # Turning the first joint 2.7 rad clockwise from the start (0.76 rad) sweeps the first link over
    # the obstacle point (-0.68, -2.09), at -1.885 rad and 2.2 from the base.
    start = plan.path[0]
    valid, reason = polyplan.check(arm, [start, start - [2.7, 0]])
    assert not valid and "motion 0" in reason
    with pytest.raises(polyplan.InputError, match=r"path\[0\]: 3 angles for an arm of 2 joints"):
        polyplan.check(arm, [[0, 0, 0]])


def test_a_plan_of_another_problem_and_an_empty_path_are_input_errors():
    a = polyplan.read_world(data("worlds", "seed004.json"))
    b = polyplan.read_world(data("worlds", "seed004.json"))
    with pytest.raises(polyplan.InputError, match="another problem"):
        polyplan.check(a, polyplan.plan(b)[0])
    with pytest.raises(polyplan.InputError, match="at least one"):
        polyplan.check(a, [])


def program_check(tmp_path, problem_file, rows):
    """`polyplan check PROBLEM PATH`'s (valid, reason) for a path of rows (exact numbers as text)."""
    import json
    from conftest import run_cli
    path = tmp_path / "path.json"
    path.write_text(json.dumps({"path": [[str(v) for v in row] for row in rows]}))
    code, out, err = run_cli("check", problem_file, str(path), "--json", "-")
    assert code in (0, 1), err
    answer = json.loads(out)
    return answer["valid"], answer["reason"]


def test_the_program_checks_rotating_and_arm_paths_as_python_does(tmp_path):
    piano = data("worlds", "rotation_piano.json")
    world = polyplan.read_world(piano)
    plan = polyplan.plan(world, planner="rotation")[0]
    exact = plan.path_exact
    assert program_check(tmp_path, piano, exact) == polyplan.check(world, exact) == (True, "")
    both = [exact[0], exact[-1]]
    assert program_check(tmp_path, piano, both) == polyplan.check(world, both)
    assert "moves and turns at once" in program_check(tmp_path, piano, both)[1]
    arm_file = data("arms", "two_link_points.json")
    arm = polyplan.read_arm(arm_file)
    swing = [[0.76, 0.12], [-1.94, 0.12]]
    assert program_check(tmp_path, arm_file, swing) == polyplan.check(arm, swing)
    assert program_check(tmp_path, arm_file, swing)[0] is False
    steady = polyplan.plan(arm, planner="grid")[0].path
    assert program_check(tmp_path, arm_file, steady.tolist()) == (True, "")
