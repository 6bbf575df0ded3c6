"""polyplan.steer answers what `polyplan steer` answers, for both models, headings given in any
form and reduced exactly, and refuses what the program refuses."""
from fractions import Fraction

import numpy as np
import pytest

import polyplan
from conftest import cli_json

PAIRS = [
    ((0, 0, 0), (10, 0, 0), 1),
    ((0, 0, 0), (0, 4, 180), 2),
    ((1, 2, 30), (-3, 5, -120), 1.5),
    ((0, 0, "1e9"), (0, 0, -80), 1),       # the same heading, reduced exactly: no motion
    ((0, 0, 0), (28, 0, 0), 1e12),         # a huge radius, straight ahead
    ((0, 0, 0), (10, 0, 90), "1e-100"),    # a tiny one turns on the spot
]


def text(pose):
    return ",".join(str(v) for v in pose)


@pytest.mark.parametrize("model", ["dubins", "reeds-shepp"])
@pytest.mark.parametrize("start, goal, radius", PAIRS)
def test_steer_answers_as_the_program(start, goal, radius, model):
    expected, error = cli_json("steer", "--model", model, "--radius", str(radius), "--from", text(start), "--to",
                               text(goal))
    assert error is None
    got = polyplan.steer(start, goal, radius=radius, model=model)
    assert {k: got[k] for k in ("length", "word", "segments")} == expected
    assert got["svg"].startswith("<svg") or "<svg" in got["svg"][:200]


def test_poses_in_numpy_and_exact_forms():
    expected = polyplan.steer((1, 2, 30), (-3, 5, -120))["length"]
    assert polyplan.steer(np.array([1.0, 2.0, 30.0]), [Fraction(-3), "5", np.int64(-120)])["length"] == expected
    assert polyplan.steer(np.array([[1.0], [2.0], [30.0]]), (-3, 5, 240))["length"] == expected


@pytest.mark.parametrize("model, count", [("dubins", 6), ("reeds-shepp", 44)])
def test_all_words_lists_every_word_as_the_program(model, count):
    start, goal = (1, 2, 30), (-3, 5, -120)
    expected, error = cli_json("steer", "--model", model, "--from", text(start), "--to", text(goal), "--all-words")
    assert error is None
    got = polyplan.steer(start, goal, model=model, all_words=True)
    assert got["words"] == expected["words"]
    assert len(got["words"]) == count
    assert sum(w["shortest"] for w in got["words"]) == 1
    lengths = [w["length"] for w in got["words"] if w["length"] is not None]
    assert min(lengths) == pytest.approx(got["length"], rel=1e-12)
    assert "words" not in polyplan.steer(start, goal, model=model)


def test_all_words_marks_infeasible_words():
    words = {w["name"]: w["length"] for w in polyplan.steer((0, 0, 0), (10, 0, 0), all_words=True)["words"]}
    assert words["RLR"] is None and words["LRL"] is None
    assert words["LSL"] == pytest.approx(10)


@pytest.mark.parametrize("start, goal, radius, model, match", [
    ((0, 0), (1, 1, 0), 1, "dubins", "start: expected a pose"),
    ((0, 0, 0), (1, 1, 0), 0, "dubins", "turning radius 0"),
    ((0, 0, 0), (1, 1, 0), 1e101, "dubins", r"expected a number in \[1e-100, 1e\+100\]"),
    ((0, 0, 0), (1e101, 1, 0), 1, "dubins", "goal\\[0\\]: 1e\\+101: overflows the supported range"),
    ((0, 0, float("nan")), (1, 1, 0), 1, "dubins", "start"),
    ((0, 0, 0), (1, 1, 0), 1, "car", "model car: expected dubins or reeds-shepp"),
])
def test_bad_input_is_an_input_error(start, goal, radius, model, match):
    with pytest.raises(polyplan.InputError, match=match):
        polyplan.steer(start, goal, radius=radius, model=model)
