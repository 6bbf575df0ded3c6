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


# --- The new surface (issue 45): Experiment, Results.write, replan and scen on grids, animate and
# search_graph(frames=...). Every bad argument is an InputError naming it, never another exception,
# a crash or a hang.

import os
import subprocess
import sys
from decimal import Decimal

OFFICE = data("worlds", "office.json")
SMALL_GRAPH = data("graphs", "small.json")
DEN = data("movingai", "maps", "den312d.map")
GRID = np.zeros((4, 4), dtype=bool)
QUERY = [[0, 0, 4, 4]]
NOT_UTF8 = "/tmp/caf\udce9"  # a name of bytes that are not UTF-8, as os.listdir gives it back
# Animations built to be refused or stepped through by hand are never saved; numpy bools offered as
# indices warn of it.
pytestmark = [pytest.mark.filterwarnings("ignore:Animation was deleted without rendering"),
              pytest.mark.filterwarnings("ignore:In future, it will be an error for 'np.bool_'")]


@pytest.fixture(autouse=True)
def no_figure_left_open():
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")


def experiment_spec(**changes):
    spec = {"name": "hostile", "problems": [{"name": "office", "file": OFFICE}],
            "planners": [{"name": "rrt", "planner": "rrt"}], "seeds": [1, 2], "time_limit": 1}
    spec.update(changes)
    return spec


@pytest.fixture(scope="module")
def experiment():
    return polyplan.Experiment(experiment_spec())


@pytest.fixture(scope="module")
def results(experiment):
    return experiment.run(progress=False, seeds=1)


def self_holding_list():
    cycle = [1]
    cycle.append(cycle)
    return cycle


@pytest.mark.parametrize("spec, folder, match", [
    (None, None, "expected a dict"),
    ([experiment_spec()], None, "expected a dict"),
    (experiment_spec(seeds=self_holding_list()), None, "holds itself"),
    (experiment_spec(seeds=[10**400]), None, r"seeds\[0\]: an integer of more than 100 digits"),
    (experiment_spec(seeds=[-1]), None, r"seeds\[0\]: expected a whole number >= 0"),
    (experiment_spec(seeds=[1j]), None, r"seeds\[0\]: .*got complex"),
    (experiment_spec(seeds=np.array([1.5], dtype=np.float16)), None, r"seeds\[0\]"),
    (experiment_spec(seeds=np.array(3)), None, "seeds: expected a non-empty array"),
    (experiment_spec(time_limit=float("nan")), None, "time_limit: nan is not a finite number"),
    (experiment_spec(time_limit="1"), None, "time_limit: expected a positive number"),
    (experiment_spec(time_limit=True), None, "time_limit: expected a positive number"),
    (experiment_spec(problems=[{"name": "a", "file": b"office.json"}]), None, r"problems\[0\]\.file: .*bytes"),
    (experiment_spec(problems=[{"name": "a", "file": "/nonexistent/office.json"}]), None, "cannot open file"),
    (experiment_spec(problems=[{"name": "a", "file": data()}]), None, "is a directory"),
    (experiment_spec(problems=[{"name": "a", "file": "/dev/zero"}]), None, "larger than the supported 64 MiB"),
    (experiment_spec(problems=[{"name": "a", "file": OFFICE + "\0.json"}]), None,
     r"problems\[0\]\.file: .*NUL character"),
    (experiment_spec(problems=[{"name": "a", "file": NOT_UTF8 + ".json"}]), None, r"problems\[0\]\.file: .*not UTF-8"),
    (experiment_spec(name="\ud800"), None, "name: .*not UTF-8"),
    (experiment_spec(planners=[{"name": "r", "planner": "rrt", "options": {"goal-bias": float("nan")}}]), None,
     "goal-bias: nan is not a finite number"),
    (experiment_spec(planners=[{"name": "r", "planner": "rrt", "options": {1: 2}}]), None,
     r"options\.1: unknown option"),
    (experiment_spec(problems=[{"name": "a", "file": OFFICE, "query": 10**30}]), None, r"problems\[0\]\.query"),
    (experiment_spec(), 3, "folder: expected a folder's path .*got int"),
    (experiment_spec(), b"/tmp", "folder: expected a folder's path .*got bytes"),
    (experiment_spec(), [data()], "folder: expected a folder's path .*got list"),
    (experiment_spec(), NOT_UTF8, "folder: .*not UTF-8"),
], ids=lambda v: repr(v)[:40] if not isinstance(v, dict) else None)
def test_a_bad_experiment_or_folder_is_an_input_error(spec, folder, match):
    refused(match, polyplan.Experiment, spec, folder=folder)


@pytest.mark.parametrize("path, match", [
    (None, "expected a file's path"),
    (b"/tmp/x.json", "got bytes"),
    ("/tmp", "is a directory"),
    ("/dev/urandom", "larger than the supported 64 MiB"),
    (NOT_UTF8 + ".json", "from_file: .*not UTF-8"),
    (OFFICE + "\0", "from_file: .*NUL character"),
    (OFFICE, "unknown key"),
])
def test_a_bad_experiment_file_is_an_input_error(path, match):
    refused(match, polyplan.Experiment.from_file, path)


class BadIndex:
    def __index__(self):
        return "2"


@pytest.mark.parametrize("options, match", [
    (dict(threads=None), "threads: expected a whole number, got NoneType"),
    (dict(threads=10**6), r"threads 1000000: expected a whole number in \[0, 256\]"),
    (dict(threads=10**5000), r"threads \(an integer of 16610 bits\)"),
    (dict(threads=-1), "threads -1"),
    (dict(threads=2.0), "threads: expected a whole number, got float"),
    (dict(threads=np.array([2])), "threads: expected a whole number, got ndarray"),
    (dict(threads=np.bool_(True)), "threads: expected a whole number, got bool_"),
    (dict(threads=BadIndex()), "threads: expected a whole number, got BadIndex"),
    (dict(seeds=0), "seeds 0"),
    (dict(seeds=3), "seeds 3: the experiment has 2 seeds"),
    (dict(seeds=2**64), r"seeds \(an integer of 65 bits\): the experiment has 2 seeds"),
    (dict(seeds=10**400), "the experiment has 2 seeds"),
    (dict(time_limit=10**400), "time_limit .*: expected a finite number of seconds > 0"),
    (dict(time_limit=float("inf")), "time_limit inf"),
    (dict(time_limit=-1e-300), "time_limit"),
    (dict(time_limit=Decimal("NaN")), "time_limit"),
    (dict(time_limit=Decimal("sNaN")), "time_limit"),
    (dict(time_limit=1j), "time_limit 1j"),
    (dict(progress=0), "progress: expected True, False or a function"),
    (dict(progress=""), "progress: expected True, False or a function"),
    (dict(progress=lambda: None), r"progress: .*cannot be called as progress\(done, total\)"),
    (dict(out=3), "out: expected a folder's path"),
    (dict(out=OFFICE), "out: .*not a folder"),
    (dict(out="/tmp/a\0b"), "out: .*NUL character"),
])
def test_bad_run_arguments_are_refused_before_anything_runs(experiment, options, match):
    refused(match, experiment.run, **options)


def test_a_scaled_experiment_whose_cost_times_leave_a_double_is_refused():
    tiny = polyplan.Experiment(experiment_spec(time_limit=1e-300))
    refused("time_limit .*out of what a double holds apart", tiny.run, time_limit=1e300, progress=False)


@pytest.mark.parametrize("time_limit", [np.float16(0.5), Fraction(1, 2), Decimal("0.5"), np.float64(0.5)],
                         ids=["float16", "Fraction", "Decimal", "float64"])
def test_a_time_limit_may_be_any_kind_of_number(experiment, time_limit):
    assert experiment.run(seeds=1, time_limit=time_limit, progress=False).experiment["time_limit"] == 0.5


def test_progress_may_be_a_numpy_bool(experiment):
    assert len(experiment.run(seeds=1, progress=np.False_)) == 1


@pytest.mark.parametrize("folder, match", [
    (None, "Results.write: folder: expected a folder's path"),
    (3, "Results.write: folder: expected a folder's path"),
    (b"/tmp/out", "got bytes"),
    ("/proc/x", "/proc/x: cannot make the folder"),
    ("/dev/null", "/dev/null: cannot make the folder"),
    ("/tmp/a\0b", "Results.write: folder: .*NUL character"),
    (NOT_UTF8, "Results.write: folder: .*not UTF-8"),
])
def test_results_refuse_a_folder_they_cannot_write(results, folder, match):
    refused(match, results.write, folder)


def test_results_are_made_by_a_run_only():
    refused("Results: made by Experiment.run", polyplan.Results, None)


def test_a_run_writes_where_it_was_asked(results, tmp_path):
    written = results.write(tmp_path / "é☃ folder")
    assert all(os.path.exists(p) for p in written) and len(written) >= 4


@pytest.mark.parametrize("where", ["spec", "run"])
def test_a_time_limit_whose_cost_times_underflow_is_refused(experiment, where):
    with pytest.raises(polyplan.InputError, match="time_limit|cost_times"):
        if where == "spec":
            polyplan.Experiment(experiment_spec(time_limit=5e-324))
        else:
            experiment.run(seeds=1, time_limit=5e-324, progress=False)


def test_an_experiment_file_naming_a_file_with_a_nul_is_refused(tmp_path):
    import json
    spec = experiment_spec(problems=[{"name": "office", "file": OFFICE + "\0junk"}])
    (tmp_path / "nul.json").write_text(json.dumps(spec))
    refused(r"problems\[0\]\.file", polyplan.Experiment.from_file, tmp_path / "nul.json")


def test_the_largest_seeds_are_taken_from_a_dict_and_beyond_them_refused_by_name():
    assert polyplan.Experiment(experiment_spec(seeds=[2**63 - 1])).runs == 1
    refused("seed=18446744073709551615", polyplan.Experiment, experiment_spec(seeds=[2**64 - 1]))
    refused("seeds", polyplan.Experiment, experiment_spec(seeds=[2**64]))


# replan on a numpy grid.

@pytest.mark.parametrize("grid, match", [
    (None, "replan: map: expected a .map file's path or a 2-d boolean array"),
    (np.array(False), r"shape \(\)"),
    (np.zeros(5, bool), r"shape \(5\)"),
    (np.zeros((2, 2, 2), bool), r"shape \(2, 2, 2\)"),
    (np.zeros((0, 5), bool), r"shape \(0, 5\)"),
    (np.zeros((3, 3)), "float64 array"),
    (np.zeros((3, 3), np.float16), "float16 array"),
    (np.zeros((3, 3), complex), "complex128 array"),
    (np.array([[0, 1], [None, 0]], dtype=object), "object array"),
    (np.array([["0", "1"], ["0", "0"]]), "<U1 array"),
    (b"den312d.map", r"\|S11 array"),
    ([[0, 1], [0]], "numpy cannot read as an array"),
    (self_holding_list(), "numpy cannot read as an array"),
    ([[0, 10**400], [0, 0]], "object array"),
    (np.array([[0, 2], [0, 0]]), r"map\[0, 1\]: 2 is neither 0 \(free\) nor 1 \(blocked\)"),
    (np.broadcast_to(np.zeros(1, bool), (100000, 100000)), "more than the supported 67108864 cells"),
    ("/nonexistent.map", "cannot open file"),
    ("/tmp", "is a directory"),
    ("/dev/zero", "larger than the supported 64 MiB"),
    (OFFICE, "expected the header lines"),
    (np.ones((4, 4), bool), r"the start \(0, 0\) is a blocked cell"),
], ids=lambda v: type(v).__name__)
def test_replan_refuses_a_bad_map(grid, match):
    refused(match, polyplan.replan, grid, (0, 0), (1, 1))


@pytest.mark.parametrize("start, goal, options, match", [
    (None, (3, 3), {}, r"start: expected \(x, y\)"),
    ((0, 0, 0), (3, 3), {}, r"start: expected \(x, y\)"),
    ((0.5, 0), (3, 3), {}, r"start: expected \(x, y\)"),
    ((10**400, 0), (3, 3), {}, r"start: expected \(x, y\)"),
    ((2**31, 0), (3, 3), {}, r"start: expected \(x, y\)"),
    ((float("nan"), 0), (3, 3), {}, r"start: expected \(x, y\)"),
    ("00", (3, 3), {}, r"start: expected \(x, y\)"),
    ((-1, 0), (3, 3), {}, r"the start \(-1, 0\) is outside the 4 x 4 map"),
    ((0, 0), (4, 4), {}, r"the goal \(4, 4\) is outside the 4 x 4 map"),
    ((0, 0), (3, 3), dict(sensor=float("nan")), "replan: sensor=nan: expected a finite number"),
    ((0, 0), (3, 3), dict(sensor=1.0), "replan: sensor=1.0"),
    ((0, 0), (3, 3), dict(sensor=None), "replan: option sensor=None"),
    ((0, 0), (3, 3), dict(sensor=2j), "replan: option sensor=2j"),
    ((0, 0), (3, 3), dict(sensor=[2]), r"replan: option sensor=\[2\]"),
    ((0, 0), (3, 3), dict(sensor=b"2"), "replan: option sensor=b'2'"),
    ((0, 0), (3, 3), dict(sensor="abc"), "replan: sensor=abc"),
    ((0, 0), (3, 3), dict(memory_mb=1e300), "replan: memory_mb=1e"),
    ((0, 0), (3, 3), dict(memory_mb=1e-300), "more than the memory budget"),
    ((0, 0), (3, 3), dict(time_limit=-1), "replan: time_limit=-1"),
    ((0, 0), (3, 3), dict(time_limit=float("inf")), "replan: time_limit=inf"),
    ((0, 0), (3, 3), dict(algorithm=None), "replan: option algorithm=None"),
    ((0, 0), (3, 3), dict(algorithm=3), "replan: algorithm=3"),
    ((0, 0), (3, 3), dict(tables=1), "replan: tables: expected True or False"),
    ((0, 0), (3, 3), dict(sensor_radius=2), "replan: option sensor_radius: no such option"),
])
def test_replan_refuses_bad_cells_and_options(start, goal, options, match):
    refused(match, polyplan.replan, GRID, start, goal, **options)


def test_replan_drives_the_smallest_maps():
    assert polyplan.replan(np.zeros((1, 1), bool), (0, 0), (0, 0)).status == "solved"
    assert polyplan.replan(GRID, (2, 2), (2, 2)).moves == 0
    assert polyplan.replan(np.array([[0, 1, 0]]), (0, 0), (2, 0)).status == "no_path"
    assert polyplan.replan(GRID, (0, 0), (3, 3), sensor=1e300, time_limit=1e300).found


@pytest.mark.parametrize("start", [(True, False), (np.bool_(True), 0), b"\x01\x00", bytearray(b"\x01\x00")],
                         ids=["bools", "numpy bool", "bytes", "bytearray"])
def test_replan_refuses_a_cell_of_bools_or_bytes(start):
    refused("start", polyplan.replan, GRID, start, (3, 3))


def test_drive_svg_refuses_a_flag_that_is_not_one():
    refused("animate", polyplan.replan(GRID, (0, 0), (3, 3)).svg, animate="x")


def test_a_drive_asked_for_tables_has_them_even_when_empty():
    drive = polyplan.replan(np.zeros((1, 1), bool), (0, 0), (0, 0), tables=True)
    assert drive.trace == [] and drive.tables == []


def test_a_grid_value_is_named_as_given():
    refused("18446744073709551615", polyplan.replan, np.array([[0, 2**64 - 1], [0, 0]], dtype=np.uint64), (0, 0),
            (1, 1))


# Paths and keyword options, which every binding reads through exact_values.cpp and keyword_options.cpp.

@pytest.mark.parametrize("call", [
    lambda: polyplan.replan(NOT_UTF8 + ".map", (0, 0), (1, 1)),
    lambda: polyplan.scen(GRID, NOT_UTF8 + ".scen"),
    lambda: polyplan.read_world(NOT_UTF8 + ".json"),
], ids=["replan map", "scen scenarios", "read_world"])
def test_a_path_that_is_not_utf8_is_an_input_error(call):
    refused("caf", call)


@pytest.mark.parametrize("call", [
    lambda: polyplan.replan(DEN + "\0junk", (60, 12), (63, 76)),
    lambda: polyplan.scen(DEN + "\0junk", np.zeros((0, 4), int)),
    lambda: polyplan.search_graph(SMALL_GRAPH + "\0junk", 0, 6),
    lambda: polyplan.read_world(OFFICE + "\0junk"),
], ids=["replan map", "scen map", "search_graph graph", "read_world"])
def test_a_path_with_a_nul_is_an_input_error(call):
    refused("(?i)nul|junk|x00", call)


@pytest.mark.parametrize("options", [dict(algorithm="\udce9"), {"\udce9": 1}, dict(sensor=10**5000),
                                     dict(sensor=np.array([2.0])), dict(sensor=np.array(2.0))],
                         ids=["surrogate value", "surrogate key", "10**5000", "1-d array", "0-d float array"])
def test_an_option_python_cannot_hand_over_is_refused_by_name(options):
    try:
        polyplan.replan(GRID, (0, 0), (3, 3), **options)  # an array of one number may be read as that number
    except polyplan.InputError as e:
        assert str(e).startswith("replan: ") and "<NULL>" not in str(e)
    else:
        assert "sensor" in options


# scen on a grid and arrays of queries.

@pytest.mark.parametrize("scenarios, match", [
    (None, "scen: scenarios: expected a .scen file's path or an \\(N, 4\\) integer array"),
    ([], r"of shape \(0,\)"),
    ([0, 0, 4, 4], r"of shape \(4,\)"),
    (np.zeros((1, 1, 4), int), r"of shape \(1, 1, 4\)"),
    ([[0.0, 0, 4, 4]], "dtype float64"),
    (np.zeros((1, 4), np.float16), "dtype float16"),
    (np.zeros((1, 4), bool), "dtype bool"),
    (np.zeros((1, 4), complex), "dtype complex128"),
    (np.array([[0, 0, 4, None]], dtype=object), "dtype object"),
    ([["0", "0", "4", "4"]], "dtype <U1"),
    ([[2**64, 0, 4, 4]], "dtype object"),
    ([[-1, 0, 4, 4]], r"scen: scenarios\[0\]: -1 is outside the 4 x 4 map"),
    ([[2**63 - 1, 0, 4, 4]], "9223372036854775807 is outside"),
    ([[5, 0, 4, 4]], "5 is outside"),
    ({0: 1}, "got dict"),
    (b"abcd", "got bytes"),
    ("/nonexistent.scen", "cannot open file"),
    ("/tmp", "is a directory"),
    (data("movingai", "scenarios", "arena.map.scen"), "the query is for a 49x49 map"),
], ids=lambda v: type(v).__name__)
def test_scen_refuses_bad_scenarios(scenarios, match):
    refused(match, polyplan.scen, GRID, scenarios)


@pytest.mark.parametrize("reference, options, match", [
    (["a"], {}, "scen: reference\\[0\\]: not a number: a"),
    ([float("inf")], {}, r"scen: reference\[0\]: not a finite number \(inf\)"),
    ([True], {}, "scen: reference\\[0\\]: expected a number, got a bool"),
    ([np.bool_(True)], {}, "scen: reference\\[0\\]: expected a number, got a bool"),
    ([1j], {}, "scen: reference\\[0\\]: expected a number .*got complex"),
    ([[1.0]], {}, "scen: reference\\[0\\]: expected a number .*got list"),
    ([Decimal("sNaN")], {}, "scen: reference\\[0\\]: not a number"),
    ([], {}, "0 lengths for 1 queries"),
    ([1.0, 2.0], {}, "2 lengths for 1 queries"),
    ("/nonexistent.csv", {}, "cannot open file"),
    (None, dict(threads=10**6), r"scen: threads=1000000: expected a whole number in \[0, 256\]"),
    (None, dict(threads=-1), "scen: threads=-1"),
    (None, dict(threads=None), "scen: option threads=None"),
    (None, dict(threads=1.5), "scen: threads=1.5"),
    (None, dict(table_mb=2**21), "scen: table_mb=2097152"),
    (None, dict(table_mb=float("nan")), "scen: table_mb=nan"),
    (None, dict(foo=1), "scen: option foo: no such option"),
], ids=lambda v: type(v).__name__)
def test_scen_refuses_bad_references_and_options(reference, options, match):
    refused(match, polyplan.scen, GRID, QUERY, reference=reference, **options)


def test_scen_answers_the_smallest_and_blocked_maps():
    assert polyplan.scen(np.zeros((1, 1), bool), [[0, 0, 1, 1]])["length"][0] == pytest.approx(2 ** 0.5)
    assert not polyplan.scen(np.ones((4, 4), bool), QUERY)["found"][0]
    assert polyplan.scen(GRID, [[2, 2, 2, 2]])["length"][0] == 0
    assert polyplan.scen(GRID, np.zeros((0, 4), int))["length"].shape == (0,)
    assert polyplan.scen(GRID, QUERY, reference=[None])["summary"]["mismatches"] == 0


def lengths_that_never_end():
    for i in range(100):
        yield 1.0
    raise AssertionError("scen read 100 reference lengths for 1 query")


@pytest.mark.parametrize("scenarios", [[[0, 0, 4, 4], [0, 0]], self_holding_list()], ids=["ragged", "holds itself"])
def test_scen_refuses_scenarios_numpy_cannot_read(scenarios):
    refused("scen: scenarios", polyplan.scen, GRID, scenarios)


def test_scen_refuses_more_queries_than_a_file_may_hold():
    rows = np.zeros((2**20 + 1, 4), dtype=np.int64)
    rows[-1] = 99  # outside the map: refused after the rows are read, whatever the check
    refused("more than the supported 1048576", polyplan.scen, GRID, rows)


@pytest.mark.parametrize("reference", [[10**400], 3, np.array(5.0), b"a", {0: 5.0}, "gen"],
                         ids=["10**400", "int", "0-d array", "bytes", "dict", "endless"])
def test_scen_refuses_a_reference_that_is_not_a_list_of_lengths(reference):
    refused("scen: reference", polyplan.scen, GRID, QUERY,
            reference=lengths_that_never_end() if reference == "gen" else reference)


CRASHES = {
    "scen reference of arrays": "polyplan.scen(np.zeros((2, 2), bool), [[0, 0, 1, 1]], reference=[np.array([1.0])])",
    "check point of arrays": "polyplan.check(polyplan.read_world(%r), [[np.array([1.0]), 1], [2, 2]])" % OFFICE,
    "plan start of a 0-d float array": "polyplan.planner('visibility', polyplan.read_world(%r))"
                                       ".plan(start=[np.array(1.0), 1], goal=[2, 2])" % OFFICE,
}


@pytest.mark.parametrize("call", list(CRASHES.values()), ids=list(CRASHES))
def test_an_array_where_a_number_goes_is_an_input_error_not_a_crash(call):
    # In a process of its own: the crash takes the process with it. Refused, or an array of one
    # number read as that number: either, not a crash.
    code = (f"import numpy as np, polyplan\ntry:\n    {call}\n    print('read')\n"
            "except polyplan.InputError:\n    print('InputError')\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and done.stdout.strip() in ("InputError", "read"), (done.returncode, done.stderr[-300:])


# search_graph: the method and weight and vertices of numpy.

@pytest.mark.parametrize("arguments", [dict(method=3), dict(method=None), dict(method="wastar", weight="two"),
                                       dict(method="wastar", weight=10**400), dict(start=np.array([0])),
                                       dict(start=np.bool_(False))],
                         ids=["method 3", "method None", "weight str", "weight 10**400", "start 1-d array",
                              "start numpy bool"])
def test_search_graph_refuses_bad_methods_weights_and_vertices(arguments):
    arguments = dict(dict(start=0, goal=6), **arguments)
    refused("method|weight|start", polyplan.search_graph, SMALL_GRAPH, **arguments)


# animate and search_graph(frames=...).

@pytest.fixture(scope="module")
def world_plan():
    return polyplan.plan(polyplan.read_world(data("worlds", "seed004.json")))[0]


@pytest.fixture(scope="module")
def searched():
    return polyplan.search_graph(SMALL_GRAPH, 0, 6)


@pytest.mark.parametrize("options, match", [
    (dict(frames=0), r"frames=0: expected a whole number in \[1, 10000\]"),
    (dict(frames=10**400), r"frames=\(an integer of 1329 bits\)"),
    (dict(frames=10**12), "frames=1000000000000"),
    (dict(frames=2.0), "frames=2.0"),
    (dict(frames="2"), "frames='2'"),
    (dict(frames=True), "frames=True"),
    (dict(frames=np.bool_(True)), "frames=True"),
    (dict(frames=float("nan")), "frames=nan"),
    (dict(interval=-1), "interval=-1: expected a number of milliseconds"),
    (dict(interval=float("nan")), "interval=nan"),
    (dict(interval="5"), "interval='5'"),
    (dict(interval=None), "interval=None"),
    (dict(interval=10**400), r"interval=\(an integer of 1329 bits\)"),
    (dict(what=None), "what=None"),
    (dict(what=["path"]), r"what=\['path'\]"),
    (dict(ax=3), "ax: expected a matplotlib Axes, got int"),
    (dict(ax="x"), "ax: expected a matplotlib Axes, got str"),
])
def test_animate_refuses_bad_options(world_plan, options, match):
    refused(match, polyplan.animate, world_plan, **options)


def collected():
    """Animations stepped through by hand are collected here, where their warning is ignored."""
    import gc
    import matplotlib.pyplot as plt
    plt.close("all")
    gc.collect()


def test_animate_takes_numpy_counts(world_plan):
    assert len(list(polyplan.animate(world_plan, frames=np.int64(3)).new_frame_seq())) == 3
    collected()


def small_graph():
    import json
    with open(SMALL_GRAPH) as f:
        return json.load(f)


def with_vertices(**fields):
    return [dict(v, **fields) for v in small_graph()]


@pytest.mark.parametrize("graph, match", [
    ("/nonexistent.json", "graph: /nonexistent.json: cannot open file"),
    ("/tmp", "graph: /tmp: is a directory"),
    (OFFICE + "\0", r"graph: .*\\x00: cannot open file"),
    ("/dev/zero", "larger than the supported 64 MiB"),
    ("/etc/hostname", "not JSON"),
    ("latin1", "not UTF-8"),
    ("deep", "not JSON"),
    (3, "graph: expected a list of dicts"),
    ([{"y": 1}] * 7, "graph: expected a list of dicts"),
    (with_vertices(x=None), r"graph\[0\]\.x: expected a point \[x, y\], got None"),
    (with_vertices(x="ab"), r"graph\[0\]\.x: expected a point"),
    (with_vertices(x=[1]), r"graph\[0\]\.x: expected a point"),
    (with_vertices(x=[0, 0, 1]), r"graph\[0\]\.x: expected a point"),
    (with_vertices(x={"a": 1}), r"graph\[0\]\.x: expected a point"),
    (with_vertices(x=[float("nan"), 0]), r"graph\[0\]\.x\[0\]: nan is not a finite number"),
    (with_vertices(neighbors=None), r"graph\[0\]\.neighbors: expected a list of vertex indices"),
    (with_vertices(neighbors="ab"), r"graph\[0\]\.neighbors: expected a list"),
    (with_vertices(neighbors=[99]), r"graph\[0\]\.neighbors\[0\]: 99 is not a vertex"),
    (with_vertices(neighbors=[-1]), r"graph\[0\]\.neighbors\[0\]: -1 is not a vertex"),
    (with_vertices(neighbors=[1.5]), r"graph\[0\]\.neighbors\[0\]: 1.5 is not a vertex"),
    (with_vertices(neighbors=[10**30]), r"graph\[0\]\.neighbors\[0\]: .* is not a vertex"),
    (small_graph()[:3], r"graph\[1\]\.neighbors\[1\]: 3 is not a vertex"),
], ids=lambda v: v if isinstance(v, str) and len(v) < 30 else type(v).__name__)
def test_animate_refuses_a_graph_that_is_not_one(searched, graph, match, tmp_path):
    if graph == "latin1":
        graph = tmp_path / "latin1.json"
        graph.write_bytes(b'[{"x": [0, 0], "name": "caf\xe9"}]')
    elif graph == "deep":
        graph = tmp_path / "deep.json"
        graph.write_text("[" * 100000 + "]" * 100000)
    refused(match, polyplan.animate, searched, graph=graph)


def changed(result, **fields):
    import copy
    out = copy.deepcopy(result)
    out.update(fields)
    return out


def every_line(result, **fields):
    return changed(result, trace=[dict(t, **fields) for t in result["trace"]])


@pytest.mark.parametrize("change, match", [
    (dict(trace=[]), "its trace is empty"),
    (dict(trace=None), "trace: expected a non-empty list of dicts, got NoneType"),
    (dict(trace="abc"), "trace: expected a non-empty list of dicts, got str"),
    (dict(trace=[1, 2]), r"trace\[0\]: expected a dict"),
    (dict(trace=[{"vertex": 0}]), r"trace\[0\]: missing step, g, h, f, backpointer, open"),
    (dict(path=[99]), r"path\[0\]: 99 is not a vertex of graph"),
    (dict(path="ab"), "path: expected a list of vertex indices"),
    (dict(cost="x"), "cost: expected a number or None"),
    (dict(vertex=-1), r"trace\[0\]\.vertex: -1 is not a vertex of graph, which has 7 vertices"),
    (dict(vertex=1.5), r"trace\[0\]\.vertex: 1.5"),
    (dict(vertex="a"), r"trace\[0\]\.vertex: 'a'"),
    (dict(vertex=10**30), r"trace\[0\]\.vertex: \(an integer of 100 bits\)"),
    (dict(g="x"), r"trace\[0\]\.g: expected a number, got 'x'"),
    (dict(h=float("nan")), r"trace\[0\]\.h: expected a number"),
    (dict(f=10**400), r"trace\[0\]\.f: expected a number"),
    (dict(step=-1), r"trace\[0\]\.step: expected a whole number >= 0"),
    (dict(open=[99]), r"trace\[0\]\.open\[0\]: 99 is not a vertex"),
    (dict(open="x"), r"trace\[0\]\.open: expected the open list's size or its vertices"),
    (dict(backpointer=99), r"trace\[0\]\.backpointer: 99 is not a vertex"),
    (dict(method="dfs", backpointer="itself"), "the backpointers go round in a circle"),
])
def test_animate_refuses_a_search_result_that_is_not_one(searched, change, match):
    if "trace" in change or "path" in change or "cost" in change:
        result = changed(searched, **change)
    elif change.get("backpointer") == "itself":  # each vertex its own backpointer: a depth-first stack without end
        result = changed(searched, method="dfs", trace=[dict(t, backpointer=t["vertex"]) for t in searched["trace"]])
    else:
        result = every_line(searched, **change)
    refused(match, polyplan.animate, result, graph=SMALL_GRAPH)


def test_a_search_result_without_path_or_cost_is_still_drawn(searched):
    for result in (changed(searched, cost=None), {"trace": searched["trace"]}, changed(searched, path=None)):
        a = polyplan.animate(result, graph=SMALL_GRAPH, frames=2)
        for frame in a.new_frame_seq():
            a._func(frame)
    del a
    collected()


@pytest.mark.parametrize("change, match", [
    (dict(world=3), "animate: world: expected the polyplan.World .* got int"),
    (dict(parameters=None), "parameters: expected the dict of the potential-field planner's options"),
    (dict(parameters={"foo": 1}), "option foo: no such option"),
    (dict(critical_points=None), "critical_points: expected a list of dicts"),
    (dict(critical_points=[{"at": [1], "kind": "minimum"}]), r"critical_points\[0\]: expected a dict"),
    (dict(critical_points=[{"at": ["a", 1], "kind": "minimum"}]), r"critical_points\[0\]: expected a dict"),
    (dict(critical_points=[3]), r"critical_points\[0\]: expected a dict"),
])
def test_animate_refuses_a_potential_result_that_is_not_one(change, match):
    world = polyplan.World.from_dict(SQUARE)
    result = {"parameters": {}, "critical_points": []}
    given = change.pop("world", world)
    result.update(change)
    refused(match, polyplan.animate, result, world=given)


@pytest.mark.parametrize("folder, match", [
    (3, "search_graph: frames: expected a folder's path .*got int"),
    (True, "got bool"),
    (b"/tmp/frames", "got bytes"),
    ([str("/tmp")], "got list"),
    ("", "got an empty str"),
    ("/proc/x", "frames: /proc/x: cannot make the folder"),
    ("/dev/null", "frames: /dev/null: cannot make the folder"),
    (OFFICE, "cannot make the folder"),
    ("/tmp/a\0b", "frames: .*a path cannot hold a NUL character"),
])
def test_search_graph_frames_refuse_a_folder_they_cannot_write(folder, match):
    refused(match, polyplan.search_graph, SMALL_GRAPH, 0, 6, frames=folder)


def test_search_graph_frames_write_into_a_folder_of_any_name(tmp_path):
    folder = tmp_path / "caf\udce9 ☃"  # bytes that are not UTF-8 too: Python writes the name it was given
    written = polyplan.search_graph([{"x": [0, 0], "neighbors": [], "neighbors_cost": []}], 0, 0,
                                    frames=folder)["frames"]
    assert len(written) == 1 and os.path.exists(written[0])


def test_plot_refuses_an_ax_that_is_not_one(world_plan):
    refused("ax", polyplan.plot, world_plan, ax=3)
