"""Python answers what the program answers on every shipped world with every planner of polygon
worlds (default options, so the same seed) and every car planner on the car's worlds, with options
set either way, and polyplan.planners()
lists what `polyplan planners` lists."""
import math

import pytest

import polyplan
from cli_agreement import WORLD_PLANNERS, as_list, agree, clockless, compare
from conftest import cli_json, data, shipped


CAR_PLANNERS = [p.name for p in polyplan.planners() if "car" in p.space]
CAR_WORLDS = [w for w in shipped("worlds") if polyplan.read_world(data("worlds", w)).car]


@pytest.mark.parametrize("world, planner", [(w, p) for w in shipped("worlds") for p in WORLD_PLANNERS
                                            if not (w in CAR_WORLDS and p in CAR_PLANNERS)])
def test_world_plans_match_the_program(world, planner):
    """A car's world is refused alike by the planners that do not steer."""
    path = data("worlds", world)
    arguments, options = clockless(planner)
    compare(["plan", path, "--planner", planner, *arguments],
            lambda: polyplan.plan(polyplan.read_world(path), planner=planner, **options))


@pytest.mark.parametrize("planner", CAR_PLANNERS)
@pytest.mark.parametrize("world", CAR_WORLDS)
def test_car_plans_match_the_program(world, planner):
    """Every car planner (rrt and its kin plan the car in a car's world), stopped by an iteration
    limit rather than the clock so that both runs give one answer."""
    path = data("worlds", world)
    compare(["plan", path, "--planner", planner, "--iterations", "3000"],
            lambda: polyplan.plan(polyplan.read_world(path), planner=planner, iterations=3000))


def test_options_reach_the_planner_as_on_the_command_line():
    path = data("worlds", "office.json")
    expected, _ = cli_json("plan", path, "--planner", "rrtconnect", "--option", "seed=3", "--option", "shortcut=false")
    agree(polyplan.plan(polyplan.read_world(path), planner="rrtconnect", seed=3, shortcut=False), as_list(expected))
    expected, _ = cli_json("plan", path, "--planner", "visibility", "--option", "search=wastar", "--option", "weight=2.5")
    agree(polyplan.plan(polyplan.read_world(path), planner="visibility", search="wastar", weight=2.5), as_list(expected))


def test_planners_lists_what_the_program_lists():
    expected, _ = cli_json("planners")
    def option(o):
        r = o.get("range")
        bounds = None if r is None else (-math.inf if r["min"] is None else r["min"], math.inf if r["max"] is None else r["max"],
                                         r["min_open"], r["max_open"])
        return (o["name"], o["kind"], o["default"], o["description"], bounds, o.get("choices", []))
    listed = [(g["space"], p["name"], p["description"], [option(o) for o in p["options"]])
              for g in expected for p in g["planners"]]
    got = [(p.space, p.name, p.description, [tuple(o) for o in p.options]) for p in polyplan.planners()]
    assert got == listed
    assert all(isinstance(p, polyplan.PlannerInfo) and all(isinstance(o, polyplan.Option) for o in p.options)
               for p in polyplan.planners())
