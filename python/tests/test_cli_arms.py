"""Python answers what the program answers on shipped arms with every arm planner (default
options, so the same seed, but stopped by iterations rather than the clock: clockless), and on
every shipped arm with its default planner."""
import pytest

import polyplan
from cli_agreement import ARM_PLANNERS, clockless, compare
from conftest import data, shipped


# As for worlds (test_cli_worlds.py): every arm planner on a two-link arm and a three-link one
# among obstacles, and every arm with its default planner.
PLANNER_ARMS = ["two_link_points.json", "three_link_forest.json"]


@pytest.mark.parametrize("planner", ARM_PLANNERS)
@pytest.mark.parametrize("arm", PLANNER_ARMS)
def test_arm_plans_match_the_program(arm, planner):
    path = data("arms", arm)
    arguments, options = clockless(planner)
    compare(["plan", path, "--planner", planner, *arguments],
            lambda: polyplan.plan(polyplan.read_arm(path), planner=planner, **options))


@pytest.mark.parametrize("arm", shipped("arms"))
def test_every_arm_with_its_default_planner_matches_the_program(arm):
    path = data("arms", arm)
    compare(["plan", path], lambda: polyplan.plan(polyplan.read_arm(path)))
