"""Arrays in: any (N, 2) array-like of numbers, numpy in any order, stride or numeric dtype, is
read as the same exact points. Arrays out: new float64 arrays the caller owns."""
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import polyplan

WORLD = {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 1], "goal": [9, 9]}
FREE = [[1, 1], [1, 9], [9, 9]]        # around the square: free
BLOCKED = [[1, 1], [9, 9]]             # through it


@pytest.fixture
def world():
    return polyplan.World.from_dict(WORLD)


def layouts(points):
    """The same points in every layout a caller may hand over."""
    c = np.array(points, dtype=float)
    wide = np.zeros((len(points), 5))
    wide[:, [1, 3]] = c
    doubled = np.repeat(c, 2, axis=0)
    return {
        "list of lists": [list(p) for p in points],
        "tuple of tuples": tuple(tuple(p) for p in points),
        "list of numpy rows": list(c),
        "C float64": c,
        "Fortran float64": np.asfortranarray(c),
        "column stride": wide[:, [1, 3]][:, :],       # a copy, then a strided view below
        "strided view": wide[:, 1:4:2],
        "row stride": doubled[::2],
        "reversed": c[::-1][::-1],
        "transposed": np.ascontiguousarray(c.T).T,
        "float32": c.astype(np.float32),
        "int64": c.astype(np.int64),
        "int8": c.astype(np.int8),
        "uint16": c.astype(np.uint16),
        "object Fractions": np.array([[Fraction(int(x)), Fraction(int(y))] for x, y in points], dtype=object),
        "strings": [[str(int(x)), str(int(y))] for x, y in points],
        "Decimals": [[Decimal(int(x)), Decimal(int(y))] for x, y in points],
        "numpy scalars": [[np.float64(x), np.int32(y)] for x, y in points],
    }


@pytest.mark.parametrize("layout", list(layouts(FREE)))
def test_every_layout_is_read_as_the_same_points(world, layout):
    assert polyplan.check(world, layouts(FREE)[layout]) == (True, "")
    valid, reason = polyplan.check(world, layouts(BLOCKED)[layout])
    assert not valid and reason


def test_strided_views_really_are_not_contiguous():
    views = layouts(FREE)
    assert not views["strided view"].flags.c_contiguous
    assert not views["row stride"].flags.c_contiguous
    assert views["Fortran float64"].flags.f_contiguous and not views["Fortran float64"].flags.c_contiguous
    assert not views["transposed"].flags.c_contiguous


def test_the_callers_array_is_not_changed(world):
    path = np.asfortranarray(np.array(FREE, dtype=float))
    before = path.copy()
    polyplan.check(world, path)
    assert np.array_equal(path, before) and path.flags.f_contiguous


def test_returned_arrays_are_new_float64_arrays_the_caller_owns(world):
    r = polyplan.planner("visibility", world).plan()
    for array in [r.path, r.expanded, r.graph.vertices, *world.obstacles, *polyplan.cspace(world).obstacles]:
        assert array.dtype == np.float64
        assert array.flags.owndata and array.flags.writeable and array.flags.c_contiguous
    assert r.graph.edges.dtype == np.int64
    first = r.path
    first[0, 0] = -100.0
    assert r.path[0, 0] != -100.0, "each access returns a new array"
    assert r.path is not r.path


def test_start_and_goal_in_any_form(world):
    p = polyplan.planner("visibility", world)
    lengths = {p.plan(start=s, goal=g).length for s, g in [
        ((1, 1), (9, 9)), ([1.0, 1.0], np.array([9, 9])), (np.array([1.0, 1.0])[::1], ("9", Fraction(9))),
        (np.array([[1, 0], [1, 0]], dtype=float)[:, 0], (Decimal(9), np.int64(9)))]}
    assert len(lengths) == 1


def test_points_as_column_and_row_vectors(world):
    # The course writes points as column vectors, np.array([[x], [y]]).
    p = polyplan.planner("visibility", world)
    expected = p.plan(start=(1, 1), goal=(9, 9)).length
    for start, goal in [(np.array([[1.0], [1.0]]), np.array([[9.0], [9.0]])), (np.array([[1, 1]]), np.array([[9, 9]]))]:
        assert p.plan(start=start, goal=goal).length == expected
    with pytest.raises(polyplan.InputError, match=r"start: expected a 1-d array of numbers, got shape \(2, 2\)"):
        p.plan(start=np.ones((2, 2)), goal=(9, 9))


def test_a_big_array_is_read_exactly(world):
    # 10001 points along the left edge: a long path, every point exact.
    ys = np.linspace(1, 9, 10001)
    path = np.column_stack([np.ones_like(ys), ys])
    assert polyplan.check(world, np.asfortranarray(path)) == (True, "")


def test_a_visibility_graph_names_each_edges_kind():
    # Two squares side by side: their sides and the two outer bitangents support, the two crossing
    # between them separate; visibility-full marks the edges not tangent at an end as "other".
    two = polyplan.World.from_dict({"bounds": [0, 0, 20, 10], "start": [1, 5], "goal": [19, 5], "obstacles": [
        [[4, 3], [7, 3], [7, 6], [4, 6]], [[12, 4], [15, 4], [15, 7], [12, 7]]]})
    r = polyplan.planner("visibility", two).plan()
    kinds = r.graph.edge_kinds
    assert len(kinds) == len(r.graph.edges) and kinds.count("supporting") == 10 and kinds.count("separating") == 2
    assert r.facts["roadmap"]["separating_edges"] == 2
    for (u, v), kind in zip(r.graph.edges, kinds):
        if kind == "separating":  # from one square to the other, crossing the line between them
            assert (r.graph.vertices[u][0] < 10) != (r.graph.vertices[v][0] < 10)
    full = polyplan.planner("visibility-full", two).plan()
    assert "other" in full.graph.edge_kinds and full.facts["roadmap"]["other_edges"] == full.graph.edge_kinds.count("other")
    assert "separating bitangents (2)" in polyplan.svg(two, r)
    assert polyplan.planner("rrt", two, seed=1).plan().graph.edge_kinds is None
