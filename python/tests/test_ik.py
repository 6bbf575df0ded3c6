"""polyplan.ik answers what `polyplan ik` answers: the same solutions, errors and free flags, with
orientations reduced exactly, and refuses what the program refuses."""
import numpy as np
import pytest

import polyplan
from conftest import cli_json, data

CASES = [
    ("two_link_points.json", (0.3, 0.4), None, False),
    ("three_link_forest.json", (1, 1), None, False),
    ("three_link_forest.json", (1, 1), "1e9", False),
    ("three_link_forest.json", (1, 1), 90, True),
    ("six_link_forest.json", (2, 1), 30, True),
]


@pytest.mark.parametrize("arm, target, orientation, collision_free", CASES)
def test_ik_answers_as_the_program(arm, target, orientation, collision_free):
    path = data("arms", arm)
    arguments = ["ik", path, "--target", f"{target[0]},{target[1]}", "--all"]
    if orientation is not None:
        arguments += ["--orientation", str(orientation)]
    if collision_free:
        arguments.append("--collision-free")
    expected, error = cli_json(*arguments)
    assert error is None
    got = polyplan.ik(polyplan.read_arm(path), target, orientation=orientation, collision_free=collision_free)
    assert {k: v for k, v in got.items() if k != "svg"} == expected
    assert "<svg" in got["svg"]


def test_targets_as_numpy_and_the_orientation_reduced_exactly():
    arm = polyplan.read_arm(data("arms", "three_link_forest.json"))
    a = polyplan.ik(arm, (1, 1), orientation=-80)
    assert polyplan.ik(arm, np.array([[1.0], [1.0]]), orientation="1e9") == a
    assert a["orientation"] == -80


@pytest.mark.parametrize("call, match", [
    (lambda arm, world: polyplan.ik(world, (1, 1)), "arm: expected a polyplan.Arm"),
    (lambda arm, world: polyplan.ik(arm, (1, 1, 1)), "target: expected a point"),
    (lambda arm, world: polyplan.ik(arm, (1, 1), orientation=float("nan")), "orientation"),
    (lambda arm, world: polyplan.ik(arm, (1, 1), all="yes"), "all: expected True or False"),
])
def test_bad_arguments_are_input_errors(call, match):
    arm = polyplan.read_arm(data("arms", "two_link_points.json"))
    world = polyplan.read_world(data("worlds", "seed004.json"))
    with pytest.raises(polyplan.InputError, match=match):
        call(arm, world)
