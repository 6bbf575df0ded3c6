"""polyplan.replan: the robot that discovers its map, from Python as from the program — the same
drive (cells, exact costs, counts), the knowledge as an array, the picture, and bad input refused."""
import numpy as np
import pytest

import polyplan
from conftest import cli_json, data

DEN = data("movingai", "maps", "den312d.map")


def test_the_drive_is_the_programs():
    drive = polyplan.replan(DEN, (60, 12), (63, 76), sensor=1.5)
    expected, error = cli_json("replan", DEN, "--start", "60,12", "--goal", "63,76", "--sensor", "1.5")
    assert error is None
    assert drive.found and drive.status == "solved"
    assert [list(c) for c in drive.traversed] == expected["traversed"]
    assert drive.traversed_cost_exact == expected["traversed_cost_exact"]
    assert (drive.moves, drive.replans, drive.expanded) == (expected["moves"], expected["replans"], expected["expanded"])
    assert [s["cost_to_goal_exact"] for s in drive.steps] == [s["cost_to_goal_exact"] for s in expected["steps"]]


def test_astar_from_scratch_drives_the_same_costs_with_more_work():
    dstar = polyplan.replan(DEN, (60, 12), (63, 76))
    astar = polyplan.replan(DEN, (60, 12), (63, 76), algorithm="astar")
    assert astar.traversed_cost_exact == dstar.traversed_cost_exact
    assert astar.expanded > 10 * dstar.expanded


def test_knowledge_and_picture():
    drive = polyplan.replan(DEN, (60, 12), (63, 76))
    k = drive.knowledge
    assert k.dtype == np.uint8 and k.shape == (81, 65)
    # Every cell it stood on is known free; blocked cells were seen.
    assert all(k[y, x] == 1 for x, y in drive.traversed)
    assert (k == 2).sum() > 0
    assert "blocked, seen" in drive.svg()
    assert "<animate" in drive.svg(animate=True)
    assert "solved" in repr(drive)


@pytest.mark.parametrize("args, message", [
    (dict(start=(0, 0), goal=(63, 76)), "the start (0, 0) is a blocked cell"),
    (dict(start=(60, 12), goal=(63, 76), sensor=1.0), "sensor radius: must be a finite number of at least √2"),
    (dict(start=(60, 12), goal=(63, 76), algorithm="bfs"), 'unknown algorithm "bfs"'),
    (dict(start="60,12", goal=(63, 76)), "start: expected (x, y)"),
])
def test_bad_input_is_an_input_error(args, message):
    with pytest.raises(polyplan.InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        polyplan.replan(DEN, **args)


def test_a_world_that_changes_is_planned_as_the_program_plans_it():
    """The world's "changes" reach the replanning planners from Python as from the program, and
    the others refuse the world, naming the change."""
    from cli_agreement import compare
    path = data("changing_worlds", "door_closes.json")
    world = polyplan.read_world(path)
    for planner in ("dstar-lite", "repeated-astar"):
        compare(["plan", path, "--planner", planner], lambda: polyplan.plan(world, planner=planner))
    plan = polyplan.plan(world, planner="dstar-lite", sensor=3)[0]
    assert plan.found and plan.facts["replan"]["changes_made"] == 3
    with pytest.raises(polyplan.InputError, match=r"changes\[0\]: the world changes as the robot drives"):
        polyplan.plan(world, planner="visibility")
