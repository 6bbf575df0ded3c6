"""Python answers what the program answers on every shipped arm with every arm planner (default
options, so the same seed)."""
import pytest

import polyplan
from cli_agreement import ARM_PLANNERS, compare
from conftest import data, shipped


@pytest.mark.parametrize("planner", ARM_PLANNERS)
@pytest.mark.parametrize("arm", shipped("arms"))
def test_arm_plans_match_the_program(arm, planner):
    path = data("arms", arm)
    compare(["arm", path, "--planner", planner], lambda: polyplan.plan(polyplan.read_arm(path), planner=planner))
