"""Python answers what the program answers for every car planner on the car's worlds (the
counterpart of test_cli_worlds.py, apart so that CTest runs the two side by side)."""
import pytest

import polyplan
from cli_agreement import compare
from conftest import data, shipped


CAR_PLANNERS = [p.name for p in polyplan.planners() if "car" in p.space]
CAR_WORLDS = [w for w in shipped("worlds") if polyplan.read_world(data("worlds", w)).car]


@pytest.mark.parametrize("planner", CAR_PLANNERS)
@pytest.mark.parametrize("world", CAR_WORLDS)
def test_car_plans_match_the_program(world, planner):
    """Every car planner (rrt and its kin plan the car in a car's world), stopped by an iteration
    limit rather than the clock so that both runs give one answer."""
    path = data("worlds", world)
    compare(["plan", path, "--planner", planner, "--iterations", "3000"],
            lambda: polyplan.plan(polyplan.read_world(path), planner=planner, iterations=3000))
