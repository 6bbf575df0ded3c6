"""Arms whose goal is a point for the hand: read from a file or given as goal_point=(x, y) (and
goal_orientation=) to Planner.plan; the plan ends with the hand at the point, its facts say which
inverse-kinematics solution it reached, an unreachable point is an answer, bad combinations are
InputError, and the picture marks the point."""
import math

import pytest

import polyplan
from conftest import data


def hand(arm, angles):
    """The end of the last link, by forward kinematics written out here."""
    x = y = heading = 0.0
    for length, angle in zip(arm.links, angles):
        heading += angle
        x += length * math.cos(heading)
        y += length * math.sin(heading)
    return x, y


@pytest.fixture
def reach():
    return polyplan.read_arm(data("arms", "two_link_reach.json"))


def test_a_file_s_goal_points_and_limits(reach):
    names = [q[0] for q in reach.queries]
    assert names == ["outer_boundary", "inner_boundary", "two_elbows", "one_elbow_free", "one_ulp_beyond"]
    assert reach.queries[0][2] == {"point": (3.0, 4.0), "orientation": None}
    assert reach.limits is None
    four = polyplan.read_arm(data("arms", "four_link_reach.json"))
    assert four.limits == [(-3.0, 3.0), (-2.8, 2.8), (-2.8, 2.8), (-2.8, 2.8)]
    assert four.queries[1][2] == {"point": (-2.0, 1.5), "orientation": 2.5}


@pytest.mark.parametrize("planner", ["grid", "rrtconnect"])
def test_every_query_of_the_file_ends_at_its_point(reach, planner):
    plans = polyplan.plan(reach, planner=planner)
    for p, (name, start, goal) in zip(plans, reach.queries):
        if name == "one_ulp_beyond":
            assert not p.found and p.status == "no_path"
            assert p.why_not == "the point (0, 5.000000000000001) is out of reach: the arm reaches distances 1 to 5 from its base"
            continue
        assert p.found, p.why_not
        x, y = hand(reach, p.path[-1])
        assert math.hypot(x - goal["point"][0], y - goal["point"][1]) <= 1e-9
        assert p.facts["goal"]["reached"] < p.facts["goal"]["candidates"]
        assert p.facts["goal"]["error"] <= 1e-12
    assert plans[2].facts["goal"]["candidates"] == 2  # two_elbows


def test_a_goal_point_given_to_plan(reach):
    planner = polyplan.planner("grid", reach, resolution=5)
    p = planner.plan(start=(2.0, 1.0), goal_point=(-2, 3))
    assert p.found and p.query == "start/goal"
    assert p.facts["goal"]["candidates"] == 2
    x, y = hand(reach, p.path[-1])
    assert math.hypot(x + 2, y - 3) <= 1e-9
    assert "goal-point" in polyplan.svg(reach, p)
    three = polyplan.Arm.from_dict({"links": [1, 0.8, 0.3]})
    oriented = polyplan.planner("rrtconnect", three).plan(start=(0, 0, 0), goal_point=(0.6, 1.1), goal_orientation=1.0)
    assert oriented.found, oriented.why_not
    assert abs(math.remainder(sum(oriented.path[-1]) - 1.0, 2 * math.pi)) <= 1e-9
    far = planner.plan(start=(2.0, 1.0), goal_point=(6, 0))
    assert not far.found and far.status == "no_path"
    assert "out of reach" in far.why_not


def test_bad_goal_points_are_input_errors(reach):
    planner = polyplan.planner("grid", reach)
    cases = [
        (dict(start=(0, 0), goal=(1, 1), goal_point=(1, 1)), "plan: give goal or goal_point, not both"),
        (dict(start=(0, 0), goal=(1, 1), goal_orientation=1), "plan: goal_orientation given without goal_point"),
        (dict(goal_point=(1, 1)), "plan: give both start and goal (or goal_point), or neither"),
        (dict(start=(0, 0), goal_point=(1, 1, 1)), "goal_point: expected (x, y), got 3 number(s)"),
        (dict(start=(0, 0), goal_point=(1, float("nan"))), "goal_point"),
        (dict(start=(0, 0), goal_point=(1, 1), query="two_elbows"), "plan: give start and goal, or query, not both"),
    ]
    for arguments, message in cases:
        with pytest.raises(polyplan.InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
            planner.plan(**arguments)
    world = polyplan.read_world(data("worlds", "seed004.json"))
    with pytest.raises(polyplan.InputError, match="not a World's"):
        polyplan.planner("visibility", world).plan(start=(2, 3), goal_point=(1, 1))
    with pytest.raises(polyplan.InputError, match="both"):
        polyplan.Arm.from_dict({"links": [1], "start": [0], "goal": [0], "goal_point": [1, 0]})
