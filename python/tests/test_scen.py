"""polyplan.scen: a MovingAI scenario answered from Python as the program answers it — the map as a
file or a numpy grid, the queries as a file or an array, reference lengths compared — and an
independent check of a small grid's lengths."""
import json
import math

import numpy as np
import pytest

import polyplan
from conftest import cli_json, data

MAP = data("movingai", "maps", "arena.map")
SCEN = data("movingai", "scenarios", "arena.map.scen")
REFERENCE = data("movingai", "reference", "arena.csv")
TIMES = ("us", "mean_us", "median_us", "batch_seconds", "preprocess_seconds", "peak_memory_mb", "threads")


def clockless(answer):
    return {"queries": [{k: v for k, v in q.items() if k not in TIMES} for q in answer["queries"]],
            "summary": {k: v for k, v in answer["summary"].items() if k not in TIMES}}


def grid_of_map(path):
    rows = open(path).read().split("\n")[4:]
    return np.array([[c not in ".G" for c in row] for row in rows if row])


def scenario_rows(path):
    lines = open(path).read().split("\n")[1:]
    return np.array([[int(f) for f in line.split("\t")[4:8]] for line in lines if line.strip()])


@pytest.fixture(scope="module")
def answered():
    return polyplan.scen(MAP, SCEN, reference=REFERENCE, threads=2)


def test_the_answers_are_the_programs(answered):
    expected, error = cli_json("scen", MAP, SCEN, "--reference", REFERENCE, "--threads", "2")
    assert error is None
    assert clockless(answered) == clockless(expected)
    assert answered["summary"]["mismatches"] == 0 and answered["summary"]["queries"] == len(answered["length"])


def test_a_grid_and_an_array_of_queries_give_the_same_answers(answered):
    grid = grid_of_map(MAP)
    queries = scenario_rows(SCEN)
    lengths = [float(line.split(",")[1]) for line in open(REFERENCE).read().split("\n")[1:] if line]
    again = polyplan.scen(grid, queries, reference=lengths, threads=1)
    assert clockless(again) == clockless(answered)
    np.testing.assert_array_equal(again["length"], answered["length"])
    assert again["found"].dtype == bool and again["found"].all()


def test_lengths_on_a_small_grid_are_the_shortest_any_angle_paths():
    # One blocked cell in the middle of a 3 x 3 map: from corner (0, 0) to corner (3, 3) the diagonal
    # crosses it, so the path bends at a corner of that cell: (0, 0) → (1, 2) → (3, 3), or its mirror.
    grid = np.zeros((3, 3), dtype=bool)
    grid[1, 1] = True
    r = polyplan.scen(grid, [[0, 0, 3, 3], [0, 0, 3, 0], [0, 0, 0, 0]])
    np.testing.assert_allclose(r["length"], [2 * math.sqrt(5), 3, 0], rtol=0, atol=1e-12)
    # Walled off: no path, NaN and found False.
    closed = np.zeros((3, 3), dtype=bool)
    closed[:, 1] = True
    r = polyplan.scen(closed, np.array([[0, 0, 3, 3]]))
    assert not r["found"][0] and math.isnan(r["length"][0]) and r["queries"][0]["length"] is None


@pytest.mark.parametrize("args, message", [
    ((np.zeros((3, 3), bool), [[0, 0, 9, 9]]), r"scenarios\[0\]: 9 is outside the 3 x 3 map"),
    ((np.zeros((3, 3), bool), [[0, 0, 1]]), r"\(N, 4\) integer array"),
    ((np.zeros((3, 3), bool), [[0.5, 0, 1, 1]]), "float64"),
    ((np.zeros(3, bool), [[0, 0, 1, 1]]), r"scen: map: .*shape \(3\)"),
    ((MAP, data("movingai", "scenarios", "den312d.map.scen")), "den312d"),
])
def test_bad_input_is_an_input_error(args, message):
    with pytest.raises(polyplan.InputError, match=message):
        polyplan.scen(*args)


def test_options_and_references_are_checked():
    grid = np.zeros((2, 2), bool)
    with pytest.raises(polyplan.InputError, match="scen: threads=-1"):
        polyplan.scen(grid, [[0, 0, 1, 1]], threads=-1)
    with pytest.raises(polyplan.InputError, match="no such option"):
        polyplan.scen(grid, [[0, 0, 1, 1]], cores=2)
    with pytest.raises(polyplan.InputError, match="2 lengths for 1 queries"):
        polyplan.scen(grid, [[0, 0, 1, 1]], reference=[1, 2])
    r = polyplan.scen(grid, [[0, 0, 1, 1]], reference=[2.0])
    assert r["summary"]["mismatches"] == 1 and r["queries"][0]["mismatch"] is True
    assert json.dumps(r["queries"])  # the queries stay plain JSON values


@pytest.mark.parametrize("options, arguments", [
    ({}, []),
    ({"search": "dijkstra"}, ["--search", "dijkstra"]),
    ({"search": "wastar", "weight": 2}, ["--search", "wastar", "--weight", "2"]),
])
def test_the_grid_answers_are_the_programs(options, arguments):
    expected, error = cli_json("grid", MAP, SCEN, *arguments)
    assert error is None
    for given in (MAP, grid_of_map(MAP)):
        answered = polyplan.grid(given, SCEN, **options)
        assert clockless(answered) == clockless(expected)
        assert answered["found"].all() and len(answered["length"]) == answered["summary"]["queries"]
    if "weight" in options:  # w-suboptimal: within twice the file's optimum, never below it
        assert answered["summary"]["bound_violations"] == 0
        assert all(q["length"] >= q["expected"] - 1e-4 for q in answered["queries"])
    else:  # optimal: the file's lengths
        assert answered["summary"]["mismatches"] == 0


def test_grid_wants_a_scenario_file_of_the_maps_size():
    with pytest.raises(polyplan.InputError, match=r"grid: scenarios: expected a \.scen file"):
        polyplan.grid(MAP, [[0, 0, 1, 1]])
    with pytest.raises(polyplan.InputError, match="arena"):
        polyplan.grid(np.zeros((3, 3), bool), SCEN)
    with pytest.raises(polyplan.InputError, match="grid: search=bfs"):
        polyplan.grid(MAP, SCEN, search="bfs")
