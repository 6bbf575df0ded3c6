"""The C-space of worlds with discs and walls from Python and the program: the cores grown by radii,
the free area exact (polygons and walls only) or certified (bounds 1e-9 apart that hold the
closed form), the picture with circles and round joins, and starts that are not free refused."""
import math
import os
from fractions import Fraction

import numpy as np
import pytest

import polyplan
from conftest import cli_json, data, run_cli


def test_a_disc_robot_round_a_square_has_its_rounded_square_taken_away():
    r, s = 0.5, 2
    world = polyplan.World.from_dict({"bounds": [-5, -5, 5, 5], "robot": {"disc": "0.5"},
                                      "obstacles": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]})
    space = polyplan.cspace(world)
    assert isinstance(space, polyplan.RoundCSpace) and space.robot == "disc"
    [core] = space.obstacles
    assert core.kind == "polygon" and core.radius == Fraction(1, 2) and core.holes == []
    assert np.array_equal(core.points, [[-1, -1], [1, -1], [1, 1], [-1, 1]])
    assert space.box == (Fraction(-9, 2), Fraction(-9, 2), Fraction(9, 2), Fraction(9, 2))
    expected = 81 - (s * s + 4 * s * r + math.pi * r * r)
    lower, upper = space.free_area_bounds
    assert space.free_area is None
    assert lower <= expected * (1 + 1e-12) and upper >= expected * (1 - 1e-12)
    assert 0 <= upper - lower <= 1e-9 * expected


def test_a_point_robot_among_polygons_and_walls_has_the_polygon_worlds_exact_area():
    polygons = {"bounds": [0, 0, 10, 8], "obstacles": [[[1, 1], [4, 1], [4, 3], [1, 3]], [[6, 2], [8, 2], [7, 5]]]}
    round_space = polyplan.cspace(polyplan.World.from_dict({**polygons, "walls": [[[5, 0], [5, 6]]]}))
    plain = polyplan.cspace(polyplan.World.from_dict(polygons))
    assert isinstance(plain, polyplan.CSpace)  # the polygon world's C-space, as before
    assert round_space.free_area == plain.free_area == Fraction(80 - 6 - 3)
    assert round_space.free_area_bounds == (71.0, 71.0)
    assert [c.kind for c in round_space.obstacles] == ["polygon", "polygon", "wall"]
    assert round_space.obstacles[2].radius == 0


def test_disc_bounds_less_the_discs():
    world = polyplan.read_world(data("worlds", "sphere_world_disc_bounds.json"))
    space = polyplan.cspace(world)
    assert space.disc is not None and space.box is None
    big = float(space.disc[2]) ** 2
    expected = math.pi * (big - sum(float(c.radius) ** 2 for c in space.obstacles))
    lower, upper = space.free_area_bounds
    assert lower <= expected * (1 + 1e-12) and upper >= expected * (1 - 1e-12)
    assert upper - lower <= 1e-9 * expected


def test_the_picture_draws_circles_round_joins_and_the_legends():
    space = polyplan.cspace(polyplan.read_world(data("worlds", "disc_robot_floor_plan.json")))
    svg = space.svg()
    assert 'stroke-linejoin="round"' in svg and 'stroke-linecap="round"' in svg and "<circle" in svg
    for label in ("free space", "C-obstacles", "walls (robot would leave the bounds)", "walls (zero thickness)"):
        assert label in svg


def test_the_program_prints_the_certified_area_and_draws_the_sphere_world(tmp_path):
    picture = os.path.join(tmp_path, "sphere.svg")
    code, out, err = run_cli("cspace", data("worlds", "sphere_world.json"), "--svg", picture)
    assert code == 0, err
    assert "robot point, C-obstacles: 4 disc(s)" in out
    assert ", certified" in out and " ≤ … ≤ " in out
    with open(picture) as f:
        svg = f.read()
    assert svg.count("<circle") >= 8  # the four C-obstacles and the four discs over them, and more
    assert "C-obstacles (= obstacles, point robot)" in svg and "discs" in svg and "bounds" in svg
    summary, why = cli_json("cspace", data("worlds", "sphere_world.json"))
    assert why is None
    expected = 400 - math.pi * (3.4 ** 2 + 1.4 ** 2 + 2.5 ** 2 + 2 ** 2)
    assert summary["area_lower"] <= expected * (1 + 1e-12) and summary["area_upper"] >= expected * (1 - 1e-12)
    assert summary["area_upper"] - summary["area_lower"] <= 1e-9 * expected
    assert not summary["exact"] and "area" not in summary
    assert summary["cobstacles"] == {"discs": 4, "walls": 0, "polygons": 0, "rounded": 0}


def test_the_program_gives_an_exact_area_as_a_fraction(tmp_path):
    world = os.path.join(tmp_path, "walls.json")
    with open(world, "w") as f:
        f.write('{"bounds": [0, 0, 3, 3], "obstacles": [[[1, 1], [2, 1], [2, 1.5]]], "walls": [[[0, 2], [3, 2]]]}')
    summary, why = cli_json("cspace", world)
    assert why is None and summary["exact"]
    assert summary["area"] == "35/4" and summary["area_double"] == 8.75
    code, out, _ = run_cli("cspace", world)
    assert code == 0 and "free area 8.75 (exact, 35/4)" in out


def test_a_start_that_is_not_free_is_refused(tmp_path):
    world = os.path.join(tmp_path, "inside.json")
    with open(world, "w") as f:
        f.write('{"bounds": [0, 0, 10, 10], "discs": [{"center": [5, 5], "radius": 2}], "start": [5, 6], "goal": [1, 1]}')
    code, out, err = run_cli("cspace", world)
    assert code == 2 and out == ""
    assert "inside.json: start/goal.start: (5, 6) is not free: it overlaps discs[0]" in err


@pytest.mark.parametrize("name", ["sphere_world", "disc_robot_floor_plan", "polygon_robot_floor_plan"])
def test_the_shipped_round_worlds_are_certified_within_1e9(name):
    lower, upper = polyplan.cspace(polyplan.read_world(data("worlds", name + ".json"))).free_area_bounds
    assert 0 < lower <= upper <= lower * (1 + 1e-9)
