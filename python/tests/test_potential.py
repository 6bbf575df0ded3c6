"""polyplan.potential: the critical points of a world's potential, from Python as from the program —
the same dict as `polyplan potential --json -`, the picture, and bad parameters refused by name."""
import pytest

import polyplan
from conftest import cli_json, data, run_cli

WALL = data("worlds", "seed002_wall.json")
TRAP = data("worlds", "u_trap.json")
# the course's planning problem set's conic attraction against its wall, searched in [-3, 3] x [-3, 3].
WALL_PARAMETERS = dict(zeta=1, d_star=0, eta=1, q_star=1, box=(-3, -3, 3, 3))


def test_the_wall_holds_one_minimum_where_pull_and_push_balance():
    # Left of the wall (x = 0) the pull 1 meets the push (1/D - 1)/D², which it equals at D = 0.68233.
    found = polyplan.potential(polyplan.read_world(WALL), **WALL_PARAMETERS)
    assert [p["kind"] for p in found["critical_points"]] == ["minimum"]
    x, y = found["critical_points"][0]["at"]
    assert x == pytest.approx(-0.68233, abs=1e-5) and y == pytest.approx(0, abs=1e-5)
    assert found["box"] == [-3, -3, 3, 3] and found["goal"] == [2, 0]


def test_the_u_trap_holds_a_minimum_and_two_saddles():
    found = polyplan.potential(polyplan.read_world(TRAP))
    kinds = sorted(p["kind"] for p in found["critical_points"])
    assert kinds == ["minimum", "saddle", "saddle"]
    for p in found["critical_points"]:
        smaller, larger = p["eigenvalues"]
        assert (smaller > 0) == (p["kind"] == "minimum") and larger > 0


@pytest.mark.parametrize("path, arguments, parameters", [
    (WALL, ["--zeta", "1", "--d-star", "0", "--eta", "1", "--q-star", "1", "--box=-3,-3,3,3"], WALL_PARAMETERS),
    (TRAP, [], {}),
    (TRAP, ["--d-star", "2", "--eta", "0.5", "--q-star", "2", "--cells", "64"], dict(d_star=2, eta=0.5, q_star=2, cells=64)),
])
def test_the_answer_is_the_programs(path, arguments, parameters):
    expected, error = cli_json("potential", path, *arguments)
    assert error is None, error
    assert polyplan.potential(polyplan.read_world(path), **parameters) == expected


def test_the_picture_is_the_programs(tmp_path):
    found = polyplan.potential(polyplan.read_world(TRAP), svg=True)
    picture = found.pop("svg")
    assert "saddle (2)" in picture  # the legend counts the critical points by kind
    assert found == polyplan.potential(polyplan.read_world(TRAP))
    code, _, error = run_cli("potential", TRAP, "--svg", str(tmp_path / "trap.svg"))
    assert code == 0, error
    assert picture == (tmp_path / "trap.svg").read_text()


@pytest.mark.parametrize("parameters, message", [
    (dict(eta=-1), r"eta -1: expected a number in \[0, inf\)"),
    (dict(d_star=-2), r"d_star -2: expected a number in \[0, inf\)"),
    (dict(q_star=float("nan")), "q_star: not a finite number"),
    (dict(zeta=True), "zeta: expected a number, got a bool"),
    (dict(cells=0), r"cells 0: expected a whole number in \[1, 4096\]"),
    (dict(cells=2.5), "cells: expected an integer"),
    (dict(box=(1, 0, 0, 1)), "box: expected XMIN < XMAX"),
    (dict(box=(0, 0, 1)), r"box: expected \(xmin, ymin, xmax, ymax\)"),
    (dict(svg=1), "svg: expected True or False"),
])
def test_bad_parameters_are_input_errors_naming_them(parameters, message):
    with pytest.raises(ValueError, match=message):
        polyplan.potential(polyplan.read_world(TRAP), **parameters)


def test_a_world_is_needed_and_a_goal_in_it():
    with pytest.raises(polyplan.InputError, match="potential: expected a polyplan.World"):
        polyplan.potential(TRAP)
    world = polyplan.World.from_dict({"obstacles": [[[0, 0], [1, 0], [1, 1]]]}, "goalless")
    with pytest.raises(polyplan.InputError, match="no start/goal: the potential needs the goal"):
        polyplan.potential(world)
