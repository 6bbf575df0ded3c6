"""polyplan.space: the sampling planners' own steering and motion test from Python (steer on the
arm's torus against an implementation written here, distance symmetric, interpolate's ends, a
blocked and a free motion, the errors), and prm's roadmap built before any query (roadmap_size),
kept by a Planner across queries and printed alike by the program."""
import math

import numpy as np
import pytest

import polyplan
from conftest import cli_json, data

BOX = {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 5], "goal": [9, 5]}
RING = {"bounds": [0, 0, 10, 10],
        "obstacles": [{"outer": [[6, 6], [9, 6], [9, 9], [6, 9]], "holes": [[[7, 7], [7, 8], [8, 8], [8, 7]]]}],
        "queries": [{"start": [1, 1], "goal": [9.5, 9.5]},
                    {"start": [1, 1], "goal": [7.5, 7.5]}]}


def arm():
    return polyplan.read_arm(data("arms", "two_link_points.json"))


def wrap(angle):
    """Into (-π, π]."""
    r = math.remainder(angle, 2 * math.pi)
    return math.pi if r == -math.pi else r


def torus_steer(a, b, step):
    """Each joint the short way round (a half turn: +π), at one rate; the distance their turns' sum."""
    delta = np.array([wrap(y - x) for x, y in zip(a, b)])
    d = np.abs(delta).sum()
    if d <= step:
        return np.mod(b, 2 * math.pi)
    return np.mod(np.asarray(a) + delta * (step / d), 2 * math.pi)


def same_angles(x, y):
    return all(abs(wrap(p - q)) < 1e-12 for p, q in zip(x, y))


def test_steer_on_the_arms_torus_matches_an_independent_implementation():
    space = polyplan.space(arm())
    assert space.dimension == 2
    rng = np.random.default_rng(48)
    for _ in range(200):
        a, b = rng.uniform(-7, 7, 2), rng.uniform(-7, 7, 2)
        step = rng.uniform(0.01, 4)
        got = space.steer(a, b, step)
        assert isinstance(got, np.ndarray) and got.shape == (2,)
        assert same_angles(got, torus_steer(a, b, step)), (a, b, step, got)
        assert space.distance(a, got) <= step + 1e-12
    # Across the seam: from 6.0 toward 0.2 goes up through 2π.
    assert same_angles(space.steer([6.0, 1], [0.2, 1], 0.1), [6.1, 1])


def test_distance_is_symmetric_and_interpolate_has_its_ends():
    rng = np.random.default_rng(1)
    world = polyplan.World.from_dict(BOX)
    for problem, low, high in ((arm(), -7, 7), (world, 0, 10)):
        space = polyplan.space(problem)
        for _ in range(50):
            a, b = rng.uniform(low, high, 2), rng.uniform(low, high, 2)
            assert space.distance(a, b) == pytest.approx(space.distance(b, a), abs=1e-12)
            start = space.interpolate(a, b, 0)
            assert same_angles(start, a) if problem is not world else np.allclose(start, a)
            end = space.interpolate(a, b, 1)
            assert space.distance(end, b) == pytest.approx(0, abs=1e-12)
    space = polyplan.space(world)
    assert np.allclose(space.interpolate([0, 0], [2, 4], 0.25), [0.5, 1])


def test_motion_is_free_is_the_certified_test():
    space = polyplan.space(polyplan.World.from_dict(BOX))
    assert not space.motion_is_free([1, 5], [9, 5])  # through the square
    assert space.motion_is_free([1, 1], [9, 1])
    assert space.motion_is_free([1, 4], [9, 4])  # along its side: contact is free
    assert not space.is_free([5, 5])
    assert np.allclose(space.steer([1, 1], [9, 1], 2), [3, 1])
    assert np.array_equal(space.steer([1, 1], [2, 1], 2), [2, 1])  # nearer than a step: b itself


def test_a_world_with_discs_has_the_round_robots_space():
    space = polyplan.space(polyplan.read_world(data("worlds", "sphere_world.json")))
    assert space.dimension == 2
    assert not space.motion_is_free([-9, 2], [0, 2])  # through the disc round (-4.4, 2)
    assert space.motion_is_free([-9, -9.5], [9, -9.5])
    with pytest.raises(polyplan.InputError, match="outside the sampling box"):
        space.distance([-11, 0], [0, 0])


def test_a_cars_space_has_poses():
    world = polyplan.read_world(data("worlds", "car_park.json"))
    space = polyplan.space(world)
    assert space.dimension == 3
    a, b = world.queries[0][1], world.queries[0][2]
    a = [float(a[0]), float(a[1]), math.radians(float(a[2]))]
    b = [float(b[0]), float(b[1]), math.radians(float(b[2]))]
    step = space.distance(a, b) / 3
    assert space.distance(a, space.steer(a, b, step)) == pytest.approx(step, rel=1e-9)


@pytest.mark.parametrize("a, message", [([1, 2, 3], "expected 2 coordinates"), ([1, float("nan")], "finite"),
                                        ([11, 5], "outside the sampling box"), ("ab", "sequence of numbers")])
def test_bad_configurations_are_input_errors(a, message):
    space = polyplan.space(polyplan.World.from_dict(BOX))
    with pytest.raises(polyplan.InputError, match=message):
        space.steer(a, [1, 1], 1)
    with pytest.raises(polyplan.InputError, match="step"):
        space.steer([1, 1], [2, 2], -1)
    with pytest.raises(polyplan.InputError, match="expected 2 coordinates"):
        polyplan.space(arm()).distance([1, 2, 3], [0, 0])


def test_a_planner_keeps_its_prebuilt_roadmap_across_queries():
    world = polyplan.World.from_dict(RING)
    planner = polyplan.planner("prm", world, roadmap_size=200, k=8, seed=3)
    first = planner.plan(query=0)
    assert first.found and first.facts["roadmap"]["samples"] == 200 and first.facts["samples"] == 0
    inside = planner.plan(query=1)  # the goal in the ring's hole
    assert inside.status == "not_found" and "start in component 0" in inside.why_not
    again = planner.plan(query=0)
    assert again.facts["raw_length"] == first.facts["raw_length"]
    assert again.facts["roadmap"] == first.facts["roadmap"]  # never grown by the queries


def test_the_program_builds_the_same_roadmap():
    path = data("arms", "two_link_points.json")
    expected, error = cli_json("plan", path, "--planner", "prm", "--roadmap-size", "150", "--k", "5", "--seed", "2")
    assert error is None
    plans = polyplan.plan(polyplan.read_arm(path), planner="prm", roadmap_size=150, k=5, seed=2)
    assert len(plans) == len(expected) == 3
    for answer, plan in zip(expected, plans):
        assert answer["roadmap"] == plan.facts["roadmap"]
        assert answer["roadmap"]["samples"] == 150
        assert answer["status"] == plan.status
