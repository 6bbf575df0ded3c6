"""Exact numbers in and out: Fractions, decimal strings and floats keep their exact values
through a World, its C-space and a plan."""
from decimal import Decimal
from fractions import Fraction

import polyplan

THIRD = Fraction(1, 3)


def box_world(**extra):
    # A triangle with exact third coordinates in a box; a point robot.
    d = {"bounds": [0, 0, 10, 10],
         "obstacles": [[[Fraction(10, 3), THIRD], [Fraction(20, 3), THIRD], [5, Fraction(22, 3)]]],
         "start": [THIRD, THIRD], "goal": [Fraction(29, 3), Fraction(29, 3)]}
    d.update(extra)
    return polyplan.World.from_dict(d)


def test_fractions_round_trip_through_a_world():
    w = box_world()
    name, start, goal = w.queries[0]
    assert start == (THIRD, THIRD) and goal == (Fraction(29, 3), Fraction(29, 3))
    assert all(isinstance(v, Fraction) for v in start + goal)
    assert w.bounds == (0, 0, 10, 10)


def test_a_float_is_the_exact_value_of_the_double():
    w = box_world(start=[0.1, 0.1])
    start = w.queries[0][1]
    assert start[0] == Fraction(0.1) == Fraction(3602879701896397, 36028797018963968)
    assert start[0] != Fraction(1, 10)


def test_decimal_strings_and_decimals_are_exact():
    w = box_world(start=["0.1", Decimal("0.1")])
    assert w.queries[0][1] == (Fraction(1, 10), Fraction(1, 10))
    w = box_world(start=["1/7", "2.5e-1"])
    assert w.queries[0][1] == (Fraction(1, 7), Fraction(1, 4))


def test_big_integers_are_exact():
    big = 2**70 + 1
    w = polyplan.World.from_dict({"obstacles": [[[big, 0], [big + 1, 0], [big, 1]]], "start": [0, 0], "goal": [1, 1]})
    assert w.queries[0][2] == (1, 1)
    assert polyplan.cspace(w).free_area is None  # unbounded


def test_free_area_is_exact():
    # 100 minus the triangle's area: base 10/3, height 7 -> 35/3.
    assert polyplan.cspace(box_world()).free_area == 100 - Fraction(35, 3)
    components = polyplan.cspace(box_world()).free_components
    assert len(components) == 1 and components[0].area == 100 - Fraction(35, 3) and len(components[0].holes) == 1


def test_path_exact_is_rational_and_ends_at_the_query():
    w = box_world()
    r = polyplan.planner("visibility", w).plan()
    assert r.found and r.certified
    exact = r.path_exact
    assert exact[0] == (THIRD, THIRD) and exact[-1] == (Fraction(29, 3), Fraction(29, 3))
    assert all(isinstance(v, Fraction) for point in exact for v in point)
    # The path turns at a corner of the triangle, exactly.
    corners = {(Fraction(10, 3), THIRD), (Fraction(20, 3), THIRD), (Fraction(5), Fraction(22, 3))}
    assert set(exact[1:-1]) <= corners and len(exact) > 2
    # The path's exact points give the float path.
    assert [tuple(map(float, p)) for p in exact] == [tuple(p) for p in r.path.tolist()]


def test_a_path_that_grazes_a_corner_is_decided_exactly():
    # The segment from (0, 1/3) to (10, 1/3) runs along the triangle's base: touching is allowed
    # (free space is closed). The doubles next to 1/3 fall on either side of it: the one below
    # passes, the one above cuts the triangle, as does 0.34.
    w = box_world()
    assert polyplan.check(w, [[0, THIRD], [10, THIRD]]) == (True, "")
    assert polyplan.check(w, [[0, "0.34"], [10, "0.34"]])[0] is False
    assert polyplan.check(w, [[0, 0.3333333333333333], [10, 0.3333333333333333]])[0] is True
    assert polyplan.check(w, [[0, 0.33333333333333337], [10, 0.33333333333333337]])[0] is False


def test_a_rotating_plan_has_exact_rotations():
    w = polyplan.read_world(__import__("conftest").data("worlds", "rotation_seed004.json"))
    for r in polyplan.plan(w, planner="rotation"):
        assert r.found, r.why_not
        for x, y, s, c in r.path_exact:
            assert s * s + c * c == 1  # a rational point of the unit circle


def test_a_tether_length_is_compared_exactly():
    # The tether bends round the apex (0.51, 0.68): 0.85 + 0.85 = 1.7 exactly (doubles: 1.7000000000000002).
    w = polyplan.World.from_dict({"bounds": [-0.5, -1, 1.5, 1.5],
                                  "obstacles": [[["0.51", "0.68"], ["0.31", -1], ["0.71", -1]]],
                                  "start": [0, 0], "goal": ["1.02", 0]})
    for length, found in [(1.7, True), (Fraction(17, 10), True), (Decimal("1.7"), True),
                          (Fraction(17, 10) - Fraction(1, 10**15), False), (1.699999999999999, False)]:
        r = polyplan.planner("tether", w, tether_length=length).plan()
        assert r.found == found, (length, r.why_not)
