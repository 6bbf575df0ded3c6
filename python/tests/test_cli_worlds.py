"""Python answers what the program answers on every shipped world with every planner of polygon
worlds (default options, so the same seed), with options set either way, and polyplan.planners()
lists what `polyplan planners` lists."""
import pytest

import polyplan
from cli_agreement import WORLD_PLANNERS, as_list, agree, compare
from conftest import cli_json, data, shipped


@pytest.mark.parametrize("planner", WORLD_PLANNERS)
@pytest.mark.parametrize("world", shipped("worlds"))
def test_world_plans_match_the_program(world, planner):
    path = data("worlds", world)
    compare(["plan", path, "--planner", planner], lambda: polyplan.plan(polyplan.read_world(path), planner=planner))


def test_options_reach_the_planner_as_on_the_command_line():
    path = data("worlds", "office.json")
    expected, _ = cli_json("plan", path, "--planner", "rrtconnect", "--option", "seed=3", "--option", "shortcut=false")
    agree(polyplan.plan(polyplan.read_world(path), planner="rrtconnect", seed=3, shortcut=False), as_list(expected))
    expected, _ = cli_json("plan", path, "--planner", "visibility", "--option", "search=wastar", "--option", "weight=2.5")
    agree(polyplan.plan(polyplan.read_world(path), planner="visibility", search="wastar", weight=2.5), as_list(expected))


def test_planners_lists_what_the_program_lists():
    expected, _ = cli_json("planners")
    listed = [(g["space"], p["name"], p["description"], [(o["name"], o["kind"], o["default"], o["description"]) for o in p["options"]])
              for g in expected for p in g["planners"]]
    got = [(p.space, p.name, p.description, [tuple(o) for o in p.options]) for p in polyplan.planners()]
    assert got == listed
    assert all(isinstance(p, polyplan.PlannerInfo) and all(isinstance(o, polyplan.Option) for o in p.options)
               for p in polyplan.planners())
