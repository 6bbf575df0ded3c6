"""Every kind of bad input raises polyplan.InputError (a ValueError) with a message that names
what is wrong; none crashes the interpreter or passes silently."""
import json
import math
from fractions import Fraction

import numpy as np
import pytest

import polyplan
from conftest import data, run_cli

SQUARE = {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 1], "goal": [9, 9]}


def raises(match, call, *args, **kwargs):
    with pytest.raises(polyplan.InputError, match=match) as caught:
        call(*args, **kwargs)
    assert isinstance(caught.value, ValueError)
    return str(caught.value)


@pytest.fixture
def world():
    return polyplan.World.from_dict(SQUARE)


@pytest.fixture
def arm():
    return polyplan.read_arm(data("arms", "two_link_points.json"))


def test_input_error_is_a_value_error():
    assert issubclass(polyplan.InputError, ValueError)


def test_the_message_is_the_programs(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"obstacles": [[[0, 0], [1, 0]]], "start": [5, 5], "goal": [6, 6]}))
    message = raises("bad.json", polyplan.read_world, str(bad))
    code, _, err = run_cli("plan", str(bad))
    assert code != 0
    assert message in err, (message, err)


@pytest.mark.parametrize("text,match", [
    ("{", "bad.json|<json>"),
    ("[]", "expected"),
    ('{"obstacles": [[[0, 0], [1, 0], [true, 1]]]}', "not a number"),
    ('{"obstacles": [[[0, 0], [1, 0], ["x", 1]]]}', "x"),
])
def test_bad_world_text(text, match):
    raises(match, polyplan.World.from_json, text)


def test_missing_file():
    raises("no_such_world.json", polyplan.read_world, "no_such_world.json")
    raises("no_such_arm.json", polyplan.read_arm, "no_such_arm.json")


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_dict_with_a_number_that_is_not_finite(value):
    d = json.loads(json.dumps(SQUARE))
    d["obstacles"][0][2][0] = value
    raises(r"obstacles\[0\]\[2\]\[0\]", polyplan.World.from_dict, d)


def test_dict_with_an_object():
    raises("start", polyplan.World.from_dict, dict(SQUARE, start=[object(), 1]))
    raises("expected a dict", polyplan.World.from_dict, [1, 2])


@pytest.mark.parametrize("name,options,match", [
    ("no-such-planner", {}, "unknown planner"),
    ("visibility", {"no_such_option": 1}, "no_such_option"),
    ("visibility", {"search": "sideways"}, "sideways"),
    ("visibility", {"weight": 0.5}, "weight"),
    ("visibility", {"weight": [3]}, "weight"),
    ("visibility", {"weight": None}, "weight"),
    ("rrt", {"seed": -1}, "seed"),
    ("rrt", {"seed": 1.5}, "seed"),
    ("rrt", {"iterations": "many"}, "iterations"),
    ("grid", {}, "Arm"),
])
def test_bad_planner_or_option(world, name, options, match):
    raises(match, polyplan.planner, name, world, **options)


def test_planner_of_another_space(arm):
    raises("World", polyplan.planner, "visibility", arm)
    raises("World|Arm", polyplan.planner, "visibility", 42)
    raises("World|Arm", polyplan.plan, "not a world")


@pytest.mark.parametrize("start,goal,match", [
    ((1, 1), None, "both"),
    ((1, 2, 3, 4), (9, 9), "start"),
    ((math.nan, 1), (9, 9), "start"),
    ((1, math.inf), (9, 9), "start"),
    ((True, 1), (9, 9), "start"),
    ("ab", (9, 9), "start"),
    (np.zeros((2, 2)), (9, 9), "start"),
    ((1, 1), [object(), 2], "goal"),
    ((1, 1), ("1/0", 2), "goal"),
    ((1, 1), (9, 9, 30), "rotation"),
])
def test_bad_start_or_goal(world, start, goal, match):
    p = polyplan.planner("visibility", world)
    raises(match, p.plan, start=start, goal=goal)


def test_bad_query_choice(world):
    p = polyplan.planner("visibility", world)
    raises("query 7", p.plan, query=7)
    raises("no query named", p.plan, query="nowhere")
    raises("query", p.plan, query=1.5)
    raises("not both", p.plan, start=(1, 1), goal=(9, 9), query=0)


def test_a_query_that_is_not_free_is_an_answer_or_an_error(world):
    p = polyplan.planner("visibility", world)
    assert p.plan(start=(5, 5), goal=(9, 9)).status == "invalid_query"
    blocked = polyplan.World.from_dict(dict(SQUARE, start=[5, 5]))
    raises("start", polyplan.plan, blocked)


@pytest.mark.parametrize("path,match", [
    ([], "at least one"),
    (np.zeros((0, 2)), "at least one"),
    (np.zeros((3, 5)), r"\(N, 2\)"),
    (np.zeros(4), r"\(N, 2\)"),
    ([[0, 0], [1]], r"path\[1\]"),
    ([[0, math.nan]], r"path\[0\]"),
    (np.array([[0, np.inf]]), "path"),
    (np.array([[True, False]]), "bool"),
    ([[True, 1]], "bool"),
    ("path", "path"),
    (42, "path"),
    ([["1/0", 0]], "path"),
    (np.array([["a", "b"]]), "path"),
    (np.array([[1 + 2j, 0]]), "path"),
])
def test_bad_path_to_check(world, path, match):
    raises(match, polyplan.check, world, path)


def test_bad_arm_angles(arm):
    p = polyplan.planner("grid", arm)
    raises("2 joint angles", p.plan, start=[0], goal=[0, 0])
    raises("start", p.plan, start=[0, math.nan], goal=[0, 0])
    raises("angles", arm.joint_positions, [0, 0, 0])
    raises("angles", arm.joint_positions, "ab")


def test_bad_picture_arguments(world, arm):
    r = polyplan.plan(world)[0]
    raises("Plan", polyplan.svg, world, 5)
    raises("Plan", polyplan.svg, world, [r, "x"])
    raises("arm", polyplan.svg, arm, r)
    raises("World|Arm", polyplan.svg, "world", r)
    raises("Plan", polyplan.plot, ["x"])


def test_exact_fraction_survives_bad_neighbours():
    # A Fraction next to a bad value: the message names the bad one.
    raises(r"start\[1\]", polyplan.World.from_dict, dict(SQUARE, start=[Fraction(1, 3), math.nan]))


def test_unknown_keys_warn_as_the_program_does():
    with pytest.warns(UserWarning, match="colour"):
        polyplan.World.from_dict(dict(SQUARE, colour="red"))
    with pytest.warns(UserWarning, match="colour"):
        polyplan.Arm.from_json(json.dumps({"links": [1, 1], "colour": "red", "start": [0, 0], "goal": [1, 1]}))


def test_warnings_made_errors_raise():
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(UserWarning, match="colour"):
            polyplan.World.from_dict(dict(SQUARE, colour="red"))


def test_arguments_of_the_wrong_type(world, tmp_path):
    import pathlib
    assert polyplan.read_world(pathlib.Path(data("worlds", "seed004.json"))).queries
    assert polyplan.read_arm(pathlib.Path(data("arms", "two_link_points.json"))).joints == 2
    raises("path", polyplan.read_world, 123)
    raises("path", polyplan.read_arm, None)
    raises("text", polyplan.World.from_json, b"{}")
    raises("name", polyplan.World.from_json, "{}", 5)
    raises("World", polyplan.cspace, 42)
    raises("World", polyplan.check, "world", [[0, 0]])
    raises("name", polyplan.planner, 5, world)
    raises("name", polyplan.plan, world, planner=["visibility"])
    p = polyplan.planner("visibility", world)
    raises("record", p.plan, record="yes")
    raises("record", p.plan_all, record=1)
    raises("strobe", polyplan.svg, world, p.plan(), strobe="yes")


def test_a_car_is_refused_by_planners_that_do_not_steer():
    car = polyplan.World.from_dict({"bounds": [0, 0, 20, 10], "obstacles": [],
                                    "robot": {"parts": [[[-1, -1], [3, -1], [3, 1], [-1, 1]]], "car": {"turning_radius": 2}},
                                    "start": [5, 5, 0], "goal": [15, 5, 180]})
    for name in ("visibility", "rotation", "trapezoid"):
        raises("robot.car", polyplan.planner, name, car)
