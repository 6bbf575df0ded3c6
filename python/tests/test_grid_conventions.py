"""Grid conventions from Python (connectivity=, corner_cutting=, diagonal_cost=, known_map=): gonum's
D* Lite cases drive as gonum states them, as the program drives them, and bad values are refused
naming the option. The cases: tests/data/gonum_dstarlite/dstarlite_cases.json (gonum/gonum,
graph/path/dynamic/dstarlite_test.go at 0679b21d, BSD-3-Clause)."""
import json
import math
import os
import re

import numpy as np
import pytest

import polyplan
from conftest import cli_json

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = json.load(open(os.path.join(ROOT, "tests", "data", "gonum_dstarlite", "dstarlite_cases.json")))["cases"]


def grid_of(case):
    return np.array([[c == "*" for c in row] for row in case["rows"]])


def cell(case, node):
    columns = len(case["rows"][0])
    return (node % columns, node // columns)


def options_of(case):
    cost = case["diagonal_cost"]
    return dict(sensor=case["radius"], connectivity=case["connectivity"], corner_cutting=case["corner_cutting"],
                diagonal_cost=cost if cost == "sqrt2" else float(cost), known_map=case["known_map"])


@pytest.mark.parametrize("case", [c for c in CASES if "unknown_wall" not in c], ids=lambda c: c["name"])
def test_gonums_cases_drive_as_gonum_states(case):
    drive = polyplan.replan(grid_of(case), cell(case, case["start"]), cell(case, case["goal"]), **options_of(case))
    assert drive.found
    assert len(drive.traversed) == len(case["drive"])
    for got, want in zip(drive.traversed, case["drive"]):
        if want is not None:
            assert tuple(got) == cell(case, want)
    assert drive.traversed_cost == pytest.approx(case["cost"], abs=1e-9)


def test_the_program_drives_the_same_with_the_same_flags(tmp_path):
    case = CASES[0]  # diagonal cost 1, corner cutting
    path = tmp_path / "fig6.map"
    rows = [row.replace("*", "@") for row in case["rows"]]
    path.write_text("type octile\nheight %d\nwidth %d\nmap\n%s\n" % (len(rows), len(rows[0]), "\n".join(rows)))
    start, goal = cell(case, case["start"]), cell(case, case["goal"])
    expected, error = cli_json("replan", str(path), "--start", "%d,%d" % start, "--goal", "%d,%d" % goal,
                               "--sensor", "1.5", "--diagonal-cost", "1", "--corner-cutting", "--known-map")
    assert error is None
    drive = polyplan.replan(str(path), start, goal, sensor=1.5, diagonal_cost=1.0, corner_cutting=True,
                            known_map=True)
    assert [list(c) for c in drive.traversed] == expected["traversed"]
    assert drive.traversed_cost_exact == expected["traversed_cost_exact"] == "4"
    assert expected["grid"] == {"connectivity": 8, "corner_cutting": True, "diagonal_cost": "1"}
    assert expected["known_map"] is True


def test_a_known_map_is_driven_without_a_detour():
    # Known from the start, the wall is gone round at once, the shortest way: one search, no detour.
    grid = np.array([[c == "*" for c in row] for row in ["...", ".*.", ".*.", ".*.", ".*."]])
    blind = polyplan.replan(grid, (0, 2), (2, 4), connectivity=4, sensor=1.0)
    known = polyplan.replan(grid, (0, 2), (2, 4), connectivity=4, sensor=1.0, known_map=True)
    assert blind.traversed_cost == 12  # gonum's dead end: down, back up, over, down
    assert known.traversed_cost == 8 and known.replans == 1  # up, over, down: 2 + 2 + 4


@pytest.mark.parametrize("options, message", [
    (dict(connectivity=6), "replan: connectivity=6: expected one of 8|4"),
    (dict(diagonal_cost=0.5), "replan: diagonal_cost=0.5: expected sqrt2 or a number in [1, 1000]"),
    (dict(diagonal_cost="two"), "replan: diagonal_cost=two: expected sqrt2 or a number of at least 1"),
    (dict(sensor=1.0), "replan: sensor=1.0: expected a number in [1.4142135623730951, inf)"),
])
def test_bad_grid_options_name_the_option(options, message):
    grid = np.zeros((3, 3), dtype=bool)
    with pytest.raises(polyplan.InputError, match=re.escape(message)):
        polyplan.replan(grid, (0, 0), (2, 2), **options)


def test_sqrt2_is_the_default_in_every_spelling():
    grid = np.zeros((3, 3), dtype=bool)
    costs = {polyplan.replan(grid, (0, 0), (2, 2), diagonal_cost=d).traversed_cost_exact
             for d in ("sqrt2", math.sqrt(2), "√2")}
    assert costs == {"2√2"}
