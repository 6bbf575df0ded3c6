"""polyplan.replan: the robot that discovers its map, from Python as from the program — the same
drive (cells, exact costs, counts), the knowledge as an array, the picture, and bad input refused."""
import json
import re

import numpy as np
import pytest

import polyplan
from conftest import cli_json, data, run_cli

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
    (dict(start=(60, 12), goal=(63, 76), sensor=1.0), "replan: sensor=1.0: expected a number in [1.4142135623730951, inf)"),
    (dict(start=(60, 12), goal=(63, 76), algorithm="bfs"), "replan: algorithm=bfs: expected one of dstar-lite|lpastar|astar"),
    (dict(start="60,12", goal=(63, 76)), "start: expected (x, y)"),
])
def test_bad_input_is_an_input_error(args, message):
    with pytest.raises(polyplan.InputError, match=re.escape(message)):
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


def test_the_json_is_the_programs_for_a_file_and_for_its_grid():
    expected, error = cli_json("replan", DEN, "--start", "60,12", "--goal", "63,76", "--algorithm", "lpastar")
    assert error is None
    from_file = polyplan.replan(DEN, (60, 12), (63, 76), algorithm="lpastar")
    grid = np.array([[c not in ".G" for c in row] for row in open(DEN).read().split("\n")[4:] if row])
    assert grid.dtype == bool and grid.shape == (81, 65)
    from_grid = polyplan.replan(grid, (60, 12), (63, 76), algorithm="lpastar")
    for drive in (from_file, from_grid):
        got = json.loads(drive.to_json())
        assert {k: v for k, v in got.items() if k != "seconds"} == {k: v for k, v in expected.items() if k != "seconds"}
    # Integers 0 and 1 are a grid too.
    assert polyplan.replan(grid.astype(np.int32), (60, 12), (63, 76)).traversed == from_grid.traversed


# The course's planning problem set's small world: a wall across the middle with a gap the robot
# discovers is closed, so that D* Lite replans.
SMALL = np.array([[0, 0, 0, 0, 0, 0],
                  [0, 0, 0, 0, 0, 0],
                  [1, 1, 1, 1, 1, 0],
                  [0, 0, 0, 0, 0, 0],
                  [0, 0, 0, 0, 0, 0]], dtype=bool)


def octile_distances(free, goal):
    """Dijkstra from the goal over the free cells (8-connected, no corner cutting, moves 1 and √2):
    an independent check of the g the search computes."""
    import heapq
    rows, columns = free.shape
    dist = np.full(free.shape, np.inf)
    gx, gy = goal
    dist[gy, gx] = 0
    heap = [(0.0, gx, gy)]
    while heap:
        d, x, y = heapq.heappop(heap)
        if d > dist[y, x]:
            continue
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                nx, ny = x + dx, y + dy
                if (dx, dy) == (0, 0) or not (0 <= nx < columns and 0 <= ny < rows) or not free[ny, nx]:
                    continue
                if dx and dy and not (free[y, nx] and free[ny, x]):
                    continue
                nd = d + (2 ** 0.5 if dx and dy else 1.0)
                if nd < dist[ny, nx] - 1e-12:
                    dist[ny, nx] = nd
                    heapq.heappush(heap, (nd, nx, ny))
    return dist


def test_tables_hold_every_replans_g_and_rhs_and_the_trace_is_the_programs(tmp_path):
    drive = polyplan.replan(SMALL, (0, 0), (0, 4), tables=True, sensor=1.5)
    assert drive.found and drive.replans >= 2
    assert len(drive.tables) == drive.replans
    replanned = [s for s in drive.steps if s["replanned"]]
    for table, step in zip(drive.tables, replanned):
        g, rhs = table["g"], table["rhs"]
        assert g.shape == rhs.shape == SMALL.shape and g.dtype == np.float64
        x, y = step["at"]
        assert g[y, x] == step["cost_to_goal"]  # the robot's cost to go is its cell's g
        assert g[4, 0] == rhs[4, 0] == 0  # the goal's
    # The last replan knows the wall and its gap: g at the robot's cell is the true distance there.
    truth = octile_distances(~SMALL, (0, 4))
    x, y = replanned[-1]["at"]
    assert drive.tables[-1]["g"][y, x] == pytest.approx(truth[y, x], abs=1e-12)
    # The trace is what `polyplan replan --rhs-trace FILE` writes, line for line.
    map_file = tmp_path / "small.map"
    rows = ["".join("@" if b else "." for b in row) for row in SMALL]
    map_file.write_text(f"type octile\nheight {SMALL.shape[0]}\nwidth {SMALL.shape[1]}\nmap\n" + "\n".join(rows) + "\n")
    code, _, err = run_cli("replan", str(map_file), "--start", "0,0", "--goal", "0,4", "--rhs-trace",
                           str(tmp_path / "trace.jsonl"))
    assert code == 0, err
    lines = [json.loads(line) for line in (tmp_path / "trace.jsonl").read_text().splitlines()]
    assert drive.trace == lines
    assert polyplan.replan(SMALL, (0, 0), (0, 4)).tables is None


@pytest.mark.parametrize("grid, message", [
    (np.zeros((3,), dtype=bool), r"2-d boolean array .* shape \(3\)"),
    (np.zeros((2, 0), dtype=bool), r"shape \(2, 0\)"),
    (np.full((2, 2), 0.5), "float64"),
    (np.array([[0, 2], [0, 0]]), r"map\[0, 1\]: 2 is neither 0"),
    ([["a"]], "<U1"),
])
def test_a_bad_grid_names_its_shape_or_cell(grid, message):
    with pytest.raises(polyplan.InputError, match=message):
        polyplan.replan(grid, (0, 0), (0, 0))


def test_options_are_the_programs():
    with pytest.raises(polyplan.InputError, match="replan: option speed: no such option"):
        polyplan.replan(SMALL, (0, 0), (0, 4), speed=2)
    with pytest.raises(polyplan.InputError, match="time_limit"):
        polyplan.replan(SMALL, (0, 0), (0, 4), time_limit=-1)
    with pytest.raises(polyplan.InputError, match="tables=True: .* 65536"):
        polyplan.replan(np.zeros((300, 300), dtype=bool), (0, 0), (1, 1), tables=True)
    assert polyplan.replan(SMALL, (0, 0), (0, 4), memory_mb=1, time_limit=0).found
