"""How the CLI agreement tests compare: a Plan's JSON is the program's JSON (times aside), its
attributes say the same as that JSON, and where the program refuses a problem Python raises
InputError with the program's message."""
import json
from fractions import Fraction

import numpy as np

import polyplan
from conftest import cli_json

ARM_PLANNERS = [p.name for p in polyplan.planners() if "arm" in p.space]
WORLD_PLANNERS = [p.name for p in polyplan.planners() if "polygon world" in p.space]


def clockless(planner):
    """Options that stop `planner` by its iteration limit, never by the clock, so that the program's
    run and Python's give one answer however loaded the machine (prm on decimal.json's sliver
    passage runs until a limit): for a planner with both limits, 20000 iterations and a time limit
    it never reaches. As (program arguments, Python keyword arguments)."""
    names = {o.name for p in polyplan.planners() if p.name == planner for o in p.options}
    if not {"time", "iterations"} <= names:
        return [], {}
    options = {"iterations": 20000, "time": 1000}
    return [a for k, v in options.items() for a in (f"--{k}", str(v))], options


def without_times(value):
    """The JSON with every measured time taken out (keys naming seconds), which no two runs share;
    a fact's numpy array or tuple (a point, points, a cell) as the JSON's list."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if "seconds" not in k}
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [without_times(v) for v in value]
    return value


def as_list(answer):
    return answer if isinstance(answer, list) else [answer]


def fraction(text):
    return Fraction(text)


def agree(plans, expected):
    assert len(plans) == len(expected)
    for r, j in zip(plans, expected):
        assert without_times(json.loads(r.to_json())) == without_times(j)
        assert r.found == j["found"] and r.status == j["status"] and r.query == j["query"]
        assert r.certified == j["certified"]
        if r.found:
            assert r.length == j["length"]
            assert r.certified_by == j["certified_by"]
            assert np.array_equal(r.path, np.array(j["path"], dtype=float).reshape(r.path.shape))
            if "path_exact" in j:
                assert r.path_exact == [tuple(fraction(v) for v in point) for point in j["path_exact"]]
        else:  # a reactive planner's walk up to where it stopped, or nothing
            assert r.length is None and r.why_not == j["why_not"]
            assert np.array_equal(r.path, np.array(j["path"], dtype=float).reshape(r.path.shape))
        for key, value in without_times(r.facts).items():
            assert without_times(j[key]) == value, key


def python_answer(call):
    try:
        return call(), None
    except polyplan.InputError as e:
        return None, str(e)


def compare(arguments, python):
    """The program run with `arguments` against python() (a list of Plan)."""
    expected, refused = cli_json(*arguments)
    plans, error = python_answer(python)
    if refused:
        assert error is not None and error in refused, (error, refused)
        return
    assert error is None, error
    agree(plans, as_list(expected))
