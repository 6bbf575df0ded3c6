"""Python answers what the program answers: every planner of polygon worlds on chosen worlds and
every world with its default planner (default options, so the same seed), options set either way;
and polyplan.planners() lists what `polyplan planners` lists. The car's worlds: test_cli_cars.py."""
import math

import pytest

import polyplan
from cli_agreement import WORLD_PLANNERS, as_list, agree, clockless, compare
from conftest import cli_json, data, shipped


CAR_WORLDS = [w for w in shipped("worlds") if polyplan.read_world(data("worlds", w)).car]


# Python and the program are two layers over one front door, so the comparison proves that Python
# converts each planner's answer, and each world, as the program does: every planner on these
# worlds (a polygon robot's, a turning robot's, a trap, a sphere world, a wall without a way round,
# a pillar to wind round), and every other world with its default planner. Every planner on every
# world, the pairs in between, is the C++ conformance suite's (tests/registry).
PLANNER_WORLDS = ["seed004.json", "rotation_seed004.json", "u_trap.json", "sphere_world_polygons.json",
                  "seed002_endless_wall.json", "tether_pillar.json"]


TURNING = {p.name for p in polyplan.planners() if "turning" in p.space}


# A planner of the turning robot plans a world whose queries do not turn as one whose queries do
# (the conformance suite runs it on every world): here, on the turning robot's world only.
@pytest.mark.parametrize("world, planner", [(w, p) for w in PLANNER_WORLDS for p in WORLD_PLANNERS
                                            if p not in TURNING or w.startswith("rotation")])
def test_world_plans_match_the_program(world, planner):
    path = data("worlds", world)
    arguments, options = clockless(planner)
    compare(["plan", path, "--planner", planner, *arguments],
            lambda: polyplan.plan(polyplan.read_world(path), planner=planner, **options))


@pytest.mark.parametrize("world", [w for w in shipped("worlds") if w not in CAR_WORLDS])
def test_every_world_with_its_default_planner_matches_the_program(world):
    path = data("worlds", world)
    compare(["plan", path], lambda: polyplan.plan(polyplan.read_world(path)))


def test_a_car_world_is_refused_alike_by_a_planner_that_does_not_steer():
    path = data("worlds", CAR_WORLDS[0])
    compare(["plan", path, "--planner", "visibility"],
            lambda: polyplan.plan(polyplan.read_world(path), planner="visibility"))


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
