"""The hardening issue's hostile inputs from Python: numbers too long to write, nesting and
cycles, numpy values in a graph, vertex indices beyond any integer type, bytes that are not UTF-8,
paths of millions of points. Each is an InputError naming what is wrong, never another exception."""
from fractions import Fraction

import numpy as np
import pytest

import polyplan
from conftest import data

SQUARE = {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 1], "goal": [9, 9]}


def refused(match, call, *args, **kwargs):
    with pytest.raises(polyplan.InputError, match=match) as caught:
        call(*args, **kwargs)
    assert str(caught.value)
    return str(caught.value)


@pytest.mark.parametrize("number", [10**5000, -(10**5000), Fraction(10**5000, 3), Fraction(1, 10**5000)],
                         ids=["int", "negative int", "Fraction", "small Fraction"])  # str() refuses them
def test_numbers_python_cannot_write_are_refused_as_too_long(number):
    world = dict(SQUARE, start=[number, 1])
    refused("more than 100 digits", polyplan.World.from_dict, world)
    refused("more than 100 digits", polyplan.check, polyplan.World.from_dict(SQUARE), [(1, 1), (number, 1)])


def test_nesting_deeper_than_a_file_may_is_refused():
    deep = [1, 1]
    for _ in range(100000):
        deep = [deep]
    refused("nested deeper than the supported 32 levels", polyplan.World.from_dict, dict(SQUARE, start=deep))


def test_a_dict_that_holds_itself_is_refused():
    world = dict(SQUARE)
    world["robot"] = world
    refused("holds itself", polyplan.World.from_dict, world)


def graph_with_numpy_fields():
    return [{"x": np.array([0.0, 0.0]), "neighbors": np.array([1]), "neighbors_cost": np.array([1.5])},
            {"x": np.array([1.0, 1.0]), "neighbors": [np.int64(0), 2], "neighbors_cost": [np.float32(1.5), 2.0]},
            {"x": [np.float64(2.0), 0], "neighbors": [1], "neighbors_cost": [2.0]}]


def test_a_graph_of_numpy_fields_searches_as_its_plain_twin():
    plain = [{"x": [0.0, 0.0], "neighbors": [1], "neighbors_cost": [1.5]},
             {"x": [1.0, 1.0], "neighbors": [0, 2], "neighbors_cost": [1.5, 2.0]},
             {"x": [2.0, 0.0], "neighbors": [1], "neighbors_cost": [2.0]}]
    got = polyplan.search_graph(graph_with_numpy_fields(), np.int64(0), np.int32(2))
    assert got["path"] == polyplan.search_graph(plain, 0, 2)["path"] == [0, 1, 2]
    assert got["cost"] == 3.5


@pytest.mark.parametrize("start", [10**30, -1, 3, -(10**30)])
def test_a_vertex_index_beyond_the_graph_is_refused(start):
    refused("not a vertex of graph", polyplan.search_graph, graph_with_numpy_fields(), start, 2)


@pytest.mark.parametrize("start", [1.0, "0", True, None])
def test_a_vertex_index_that_is_not_an_integer_is_refused(start):
    refused("expected a vertex index", polyplan.search_graph, graph_with_numpy_fields(), start, 2)


def test_bytes_that_are_not_utf8_are_shown_escaped(tmp_path):
    bad = tmp_path / "latin1.json"
    bad.write_bytes(b'{"bounds": [0, 0, 10, 10], "obstacles": [], "start": [1, 1], "goal": [9, 9], "name": "caf\xe9"}')
    message = refused("latin1.json", polyplan.read_world, str(bad))
    assert "\\x" in message or "UTF-8" in message


def test_a_path_of_millions_of_points_is_refused_before_it_is_read():
    world = polyplan.World.from_dict(SQUARE)
    path = np.zeros((2_000_000, 2))
    refused("more than the supported 1048576", polyplan.check, world, path)


def test_a_planner_given_the_shipped_world_still_answers_after_every_refusal():
    # The refusals above leave nothing behind: a plan afterwards is as it always is.
    plans = polyplan.plan(polyplan.read_world(data("worlds", "seed004.json")))
    assert plans and all(p.found for p in plans)
