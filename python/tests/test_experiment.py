"""polyplan.Experiment: the experiment `polyplan benchmark` runs, from Python, with the program's
answers (every run that stops by its own rule, not the clock, gives the same record), its files,
numpy columns and a DataFrame, and InputError for what the program refuses."""
import json
import math
import os

import numpy as np
import pytest

import polyplan
from conftest import clockless, data, run_cli

# rrt stops at its first solution (and shortcuts it): the same seed gives the same path wherever
# it runs, so the records can be compared with the program's.
SPEC = {
    "name": "parity",
    "problems": [{"name": "office", "file": data("worlds", "office.json")},
                 {"name": "seed004", "file": data("worlds", "seed004.json")}],
    "planners": [{"name": "rrt-bias0.2", "planner": "rrt", "options": {"goal-bias": 0.2}},
                 {"name": "rrtconnect", "planner": "rrtconnect"}],
    "seeds": [1, 2, 3],
    "time_limit": 100,
}


@pytest.fixture(scope="module")
def results():
    return polyplan.Experiment(SPEC).run(threads=2, progress=False)


def test_runs_are_the_programs_runs(results, tmp_path):
    spec_file = tmp_path / "parity.json"
    spec_file.write_text(json.dumps(SPEC))
    code, out, err = run_cli("benchmark", str(spec_file), "--threads", "2", "--out", str(tmp_path / "cli"))
    assert code == 0, err
    program = json.loads((tmp_path / "cli" / "results.json").read_text())
    assert len(results.records) == len(program["runs"]) == 2 * 2 * 3
    assert [clockless(r) for r in results.records] == [clockless(r) for r in program["runs"]]
    without_file = [{k: v for k, v in e.items() if k != "file"} for e in (results.experiment, program["experiment"])]
    assert without_file[0] == without_file[1]
    # The same files, by name, from Results.write.
    written = results.write(tmp_path / "python")
    assert sorted(os.path.basename(p) for p in written) == sorted(os.listdir(tmp_path / "cli"))


def test_every_length_is_at_least_the_shortest_path(results):
    shortest = {}
    for problem in SPEC["problems"]:
        world = polyplan.read_world(problem["file"])
        shortest[problem["name"]] = polyplan.plan(world, planner="visibility")[0].length
    solved = [r for r in results.records if r["solved"]]
    assert len(solved) == len(results.records)  # both planners solve both worlds within their limits
    for r in solved:
        assert r["length"] >= shortest[r["problem"]] - 1e-9, r


def test_columns_are_the_records_as_arrays(results):
    c = results.columns
    n = len(results.records)
    assert c["seed"].dtype == np.int64 and c["solved"].dtype == bool and c["time"].dtype == float
    assert list(c["problem"]) == [r["problem"] for r in results.records]
    assert c["solved"].sum() == sum(r["solved"] for r in results.records)
    np.testing.assert_array_equal(c["length"], [r["length"] for r in results.records])
    assert c["cost_at"].shape == (n, len(results.experiment["cost_times"]))
    assert np.array_equal(c["facts.iterations"], [r["facts"]["iterations"] for r in results.records])
    # The last cost time is the time limit: every run's best length by then is its length.
    np.testing.assert_array_equal(c["cost_at"][:, -1], c["length"])


def test_to_pandas_has_a_row_per_run(results):
    pandas = pytest.importorskip("pandas")
    frame = results.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == len(results.records)
    assert frame.groupby("planner")["solved"].mean().to_dict() == {"rrt-bias0.2": 1.0, "rrtconnect": 1.0}
    assert f"cost_at_{results.experiment['cost_times'][-1]:g}" in frame.columns


def test_from_file_resolves_its_problems_beside_it_and_scales_down():
    exp = polyplan.Experiment.from_file(data("experiments", "seed003_rrt_rrtstar.json"))
    assert exp.problems == ["office", "maze"] and exp.runs == 2 * 9 * 10
    calls = []
    r = exp.run(threads=2, seeds=1, time_limit=0.05, progress=lambda done, total: calls.append((done, total)))
    assert len(r) == 18 and r.experiment["time_limit"] == 0.05
    assert sorted(calls) == [(k, 18) for k in range(1, 19)]
    assert math.isclose(r.experiment["cost_times"][-1], 0.05)


def test_a_dicts_files_resolve_against_its_folder():
    spec = dict(SPEC, problems=[{"name": "office", "file": "worlds/office.json"}], seeds=[1])
    assert len(polyplan.Experiment(spec, folder=data()).run(progress=False)) == 2
    with pytest.raises(polyplan.InputError, match="office.json"):
        polyplan.Experiment(spec, folder="/nonexistent")


@pytest.mark.parametrize("spec, message", [
    ([], "expected a dict"),
    ({"name": "x"}, "missing"),
    (dict(SPEC, seeds=[]), "seeds"),
    (dict(SPEC, planners=[{"name": "a", "planner": "rrt", "options": {"k": 3}}]), "k"),
    (dict(SPEC, planners=[{"name": "a", "planner": "nope"}]), "nope"),
])
def test_a_bad_experiment_names_what_is_wrong(spec, message):
    with pytest.raises(polyplan.InputError, match=message):
        polyplan.Experiment(spec)


@pytest.mark.parametrize("options, message", [
    ({"threads": -1}, "threads -1"),
    ({"threads": "2"}, "threads"),
    ({"seeds": 4}, "seeds 4: the experiment has 3 seeds"),
    ({"time_limit": 0}, "time_limit"),
    ({"time_limit": float("nan")}, "time_limit"),
    ({"progress": 3}, "progress"),
])
def test_bad_run_arguments_are_input_errors(options, message):
    with pytest.raises(polyplan.InputError, match=message):
        polyplan.Experiment(SPEC).run(**options)
