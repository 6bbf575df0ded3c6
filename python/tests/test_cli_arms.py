"""Python answers what the program answers on every shipped arm with every arm planner (default
options, so the same seed, but stopped by iterations rather than the clock: clockless)."""
import pytest

import polyplan
from cli_agreement import ARM_PLANNERS, clockless, compare
from conftest import data, shipped


@pytest.mark.parametrize("planner", ARM_PLANNERS)
@pytest.mark.parametrize("arm", shipped("arms"))
def test_arm_plans_match_the_program(arm, planner):
    path = data("arms", arm)
    arguments, options = clockless(planner)
    compare(["plan", path, "--planner", planner, *arguments],
            lambda: polyplan.plan(polyplan.read_arm(path), planner=planner, **options))
