"""polyplan.search_graph: the course's graph-search homework's graphs from Python as from `polyplan search` — the same path,
cost, counts and trace, from a file or from the list of dicts — and bad graphs refused; g and backpointer written
back into the caller's dicts, uniform-cost, bidirectional and weighted A* against an independent Dijkstra."""
import json
import math
import random

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


# The course's graph: g and backpointer written back, uniform-cost, bidirectional, weighted A*'s reopening.

SMALL = data("graphs", "small.json")


def dijkstra_from(vertices, start):
    """An independent Dijkstra (heapq): the cost from start of every vertex, inf where unreachable."""
    import heapq
    cost = [math.inf] * len(vertices)
    cost[start] = 0.0
    heap = [(0.0, start)]
    while heap:
        d, u = heapq.heappop(heap)
        if d > cost[u]:
            continue
        for v, c in zip(vertices[u]["neighbors"], vertices[u]["neighbors_cost"]):
            if d + c < cost[v]:
                cost[v] = d + c
                heapq.heappush(heap, (cost[v], v))
    return cost


def random_digraph(seed, n):
    """Points in a 100 x 100 square with out-edges to random others, each costing its length times a
    factor in [1, 3] (asymmetric, and the Euclidean heuristic consistent)."""
    rng = random.Random(seed)
    at = [[rng.uniform(0, 100), rng.uniform(0, 100)] for _ in range(n)]
    vertices = []
    for u in range(n):
        out = [rng.randrange(n) for _ in range(rng.randint(1, 5))]
        costs = [math.dist(at[u], at[v]) * rng.uniform(1, 3) for v in out]
        vertices.append({"x": at[u], "neighbors": out, "neighbors_cost": costs, "g": 0.0, "backpointer": None})
    return vertices


def loaded(path):
    with open(path) as f:
        return json.load(f)


def test_write_back_leaves_the_optimal_g_and_backpointers_in_the_callers_dicts():
    # An isolated goal: Dijkstra exhausts the start's component, so every g it leaves is optimal.
    for vertices, start in [(loaded(SMALL), 0), (loaded(MEDIUM), 5), (random_digraph(1, 60), 3)]:
        vertices.append({"x": [1000, 1000], "neighbors": [], "neighbors_cost": []})
        goal = len(vertices) - 1
        expected = dijkstra_from(vertices, start)
        result = polyplan.search_graph(vertices, start, goal, method="dijkstra", write_back=True)
        assert not result["found"]
        for v, vertex in enumerate(vertices):
            assert vertex["g"] == pytest.approx(expected[v], rel=1e-12), v
            assert vertex["g"] == result["g"][v] and vertex["backpointer"] == result["backpointer"][v]
            b = vertex["backpointer"]
            if v == start or expected[v] == math.inf:
                assert b is None, v
                continue
            # The backpointer is the vertex it was reached from, along an edge of the right cost.
            edge = min(c for n, c in zip(vertices[b]["neighbors"], vertices[b]["neighbors_cost"]) if n == v)
            assert vertex["g"] == pytest.approx(vertices[b]["g"] + edge, rel=1e-12), v
        assert vertices[goal]["g"] == math.inf and vertices[goal]["backpointer"] is None


def test_written_backpointers_lead_from_the_goal_to_the_start_along_the_path():
    vertices = loaded(MEDIUM)
    result = polyplan.search_graph(vertices, 0, 37, write_back=True)
    path, v = [], 37
    while v is not None:
        path.insert(0, v)
        v = vertices[v]["backpointer"]
    assert path == result["path"]
    assert vertices[37]["g"] == pytest.approx(result["cost"], rel=1e-15)


def test_write_back_needs_the_list_and_is_asked_for():
    with pytest.raises(polyplan.InputError, match="write_back: needs the graph as the list of dicts"):
        polyplan.search_graph(MEDIUM, 0, 37, write_back=True)
    with pytest.raises(polyplan.InputError, match="write_back: bidirectional"):
        polyplan.search_graph(loaded(MEDIUM), 0, 37, method="bidirectional", write_back=True)
    with pytest.raises(polyplan.InputError, match="frames: bidirectional records no expansions"):
        polyplan.search_graph(MEDIUM, 0, 37, method="bidirectional", frames="unused")
    with pytest.raises(polyplan.InputError, match="write_back: expected True or False"):
        polyplan.search_graph(loaded(MEDIUM), 0, 37, write_back=1)
    untouched = loaded(MEDIUM)
    polyplan.search_graph(untouched, 0, 37)
    assert untouched == loaded(MEDIUM)


def test_uniform_cost_is_dijkstra():
    for graph, start, goal in [(MEDIUM, 0, 37), (MEDIUM, 37, 5), (SMALL, 6, 2)]:
        uniform = polyplan.search_graph(graph, start, goal, method="uniform-cost")
        dijkstra = polyplan.search_graph(graph, start, goal, method="dijkstra")
        assert uniform["method"] == "dijkstra"
        for key in ("path", "cost", "expanded", "generated", "expansion_order", "trace", "g", "backpointer"):
            assert uniform[key] == dijkstra[key], key


def test_bidirectional_finds_dijkstras_cost_on_directed_graphs():
    cases = [(loaded(SMALL), s, t) for s in range(7) for t in range(7)]
    cases += [(loaded(MEDIUM), 0, 37), (loaded(MEDIUM), 37, 0), (loaded(MEDIUM), 5, 30)]
    rng = random.Random(48)
    for seed in range(5):
        vertices = random_digraph(seed, 80)
        cases += [(vertices, rng.randrange(80), rng.randrange(80)) for _ in range(20)]
    for vertices, start, goal in cases:
        optimal = dijkstra_from(vertices, start)[goal]
        both = polyplan.search_graph(vertices, start, goal, method="bidirectional")
        assert both["method"] == "bidirectional" and both["g"] is None and both["backpointer"] is None
        assert both["found"] == (optimal < math.inf), (start, goal)
        if not both["found"]:
            continue
        assert both["cost"] == pytest.approx(optimal, rel=1e-12), (start, goal)
        path = both["path"]
        assert path[0] == start and path[-1] == goal
        walked = sum(min(c for n, c in zip(vertices[u]["neighbors"], vertices[u]["neighbors_cost"]) if n == v)
                     for u, v in zip(path, path[1:]))  # every step an edge, in its direction
        assert walked == pytest.approx(both["cost"], rel=1e-12)


def test_weighted_astar_stays_within_w_of_the_optimum_with_or_without_reopening():
    for seed in range(5):
        vertices = random_digraph(100 + seed, 80)
        rng = random.Random(seed)
        for _ in range(10):
            start, goal = rng.randrange(80), rng.randrange(80)
            optimal = dijkstra_from(vertices, start)[goal]
            for weight in (1.5, 3, 20):
                textbook = polyplan.search_graph(vertices, start, goal, method="wastar", weight=weight)
                reopening = polyplan.search_graph(vertices, start, goal, method="wastar", weight=weight, reopen=True)
                for r in (textbook, reopening):
                    assert r["found"] == (optimal < math.inf)
                    if r["found"]:
                        assert optimal * (1 - 1e-12) <= r["cost"] <= weight * optimal * (1 + 1e-9)
                assert textbook["expanded"] <= textbook["generated"]
                assert len(set(textbook["expansion_order"])) == textbook["expanded"]
