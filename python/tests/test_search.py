"""polyplan.search_graph: the course's graph-search homework's graphs from Python as from `polyplan search` — the same path,
cost, counts and trace, from a file or from the list of dicts — and bad graphs refused."""
import json

import pytest

import polyplan
from conftest import cli_json, data

MEDIUM = data("graphs", "grid_medium.json")


def test_the_search_is_the_programs():
    r = polyplan.search_graph(MEDIUM, 0, 37)
    expected, error = cli_json("search", MEDIUM, "--start", "0", "--goal", "37")
    assert error is None
    assert r["found"] and r["path"] == expected["path"] and r["cost"] == expected["cost"]
    assert r["expansion_order"] == expected["expansion_order"]
    assert [t["vertex"] for t in r["trace"]] == r["expansion_order"]
    assert all(abs(t["f"] - t["g"] - t["h"]) < 1e-12 for t in r["trace"])
    assert "<svg" in r["svg"] and r["animation"].count('<circle class="expanded"') == r["expanded"]


def test_a_list_of_dicts_is_a_graph():
    with open(MEDIUM) as f:
        vertices = json.load(f)
    assert polyplan.search_graph(vertices, 0, 37, method="dijkstra")["cost"] == polyplan.search_graph(MEDIUM, 0, 37)["cost"]


def test_bad_graphs_name_the_vertex():
    with pytest.raises(polyplan.InputError, match=r"graph: vertices\[0\]\.neighbors\[0\]: index 3 outside \[0, 1\)"):
        polyplan.search_graph([{"x": [0, 0], "neighbors": [3], "neighbors_cost": [1]}], 0, 0)
    with pytest.raises(polyplan.InputError, match="goal 5: not a vertex"):
        polyplan.search_graph([{"x": [0, 0], "neighbors": [], "neighbors_cost": []}], 0, 5)
