"""polyplan.animate: every kind of answer moves, saved as a GIF of more than one frame;
search_graph(frames=...) draws a plot after every node expansion; Jupyter's pictures; plot's
labels for a plan that stopped short and for a planner's options."""
import json
from types import SimpleNamespace

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
from PIL import Image

import polyplan
from conftest import data
from polyplan import animation, plotting

matplotlib.use("Agg")

SMALL = data("graphs", "small.json")
MEDIUM = data("graphs", "grid_medium.json")
FRAMES = 5  # few, for speed: each frame is drawn twice and encoded


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def gif_frames(animation_, tmp_path):
    """The number of frames of the animation saved as a GIF."""
    out = tmp_path / "animation.gif"
    animation_.save(out, writer="pillow")
    with Image.open(out) as image:
        return image.n_frames


def first_plan(folder, name, **options):
    path = data(folder, name)
    problem = polyplan.read_arm(path) if folder == "arms" else polyplan.read_world(path)
    return polyplan.plan(problem, **options)[0]


@pytest.mark.parametrize("name", ["seed004.json", "rotation_piano.json", "car_u_turn.json"])
def test_a_robot_moves_along_its_path_from_start_to_goal(name, tmp_path):
    """A translating robot, a rotating one, a car: as many frames as asked, from the path's start to its end."""
    plan = first_plan("worlds", name)
    assert plan.found
    assert gif_frames(polyplan.animate(plan, frames=FRAMES), tmp_path) == FRAMES
    poses = animation._poses(plan, FRAMES)
    assert poses.shape == (FRAMES, plan.path.shape[1])
    np.testing.assert_allclose(poses[[0, -1], :2], plan.path[[0, -1], :2], atol=1e-9)


def test_a_car_drives_its_arcs():
    """Each segment driven to its end reaches the next one's start: arcs of the world's turning radius,
    forwards and in reverse."""
    plan = first_plan("worlds", "car_parallel_parking.json")
    segments = plan.segments
    assert {s["gear"] for s in segments} == {1, -1} and {s["steer"] for s in segments} == {"L", "S", "R"}
    ends = np.cumsum([s["length"] for s in segments]) - 1e-9
    reached = plotting.car_poses(segments, plan.problem.car["turning_radius"], ends)
    expected = np.array([s["start"] for s in segments[1:]] + [plan.path[-1]])
    turn = (reached[:, 2] - expected[:, 2] + 180) % 360 - 180
    assert np.abs(reached[:, :2] - expected[:, :2]).max() < 1e-6 and np.abs(turn).max() < 1e-6


def test_an_arm_moves_through_its_configurations(tmp_path):
    plan = first_plan("arms", "two_link_points.json")
    assert gif_frames(polyplan.animate(plan, frames=FRAMES), tmp_path) > 1


def test_a_plans_search_grows_then_shows_the_path(tmp_path):
    plan = first_plan("worlds", "seed004.json")
    assert len(plan.expanded) > FRAMES
    assert gif_frames(polyplan.animate(plan, what="search", frames=FRAMES), tmp_path) == FRAMES
    with pytest.raises(polyplan.InputError, match="recorded no expanded configurations"):
        polyplan.animate(polyplan.planner("visibility", plan.problem).plan(record=False), what="search")


def test_a_graph_search_step_by_step(tmp_path):
    result = polyplan.search_graph(SMALL, 0, 6)
    assert gif_frames(polyplan.animate(result, graph=SMALL), tmp_path) == len(result["trace"]) + 1  # and the path
    with open(SMALL) as f:
        as_numpy = [{key: np.asarray(value) for key, value in vertex.items()} for vertex in json.load(f)]
    assert gif_frames(polyplan.animate(result, graph=as_numpy, frames=3), tmp_path) == 3
    with pytest.raises(polyplan.InputError, match="graph="):
        polyplan.animate(result)


@pytest.mark.parametrize("method", ["astar", "dijkstra", "bfs", "greedy", "wastar", "dfs"])
def test_the_open_list_drawn_has_the_size_the_trace_gives(method):
    """The trace gives the open list's size once the expanded vertex is out of it (the depth-first
    stack's for dfs); the list drawn after step i is the one the next step takes its vertex from."""
    result = polyplan.search_graph(MEDIUM, 0, 37, method=method)
    trace, steps = result["trace"], animation.search_steps(MEDIUM, result)
    drawn = [len(animation._open_after(steps, i)) for i in range(len(trace))]
    if method == "dfs":
        assert drawn == [t["open"] for t in trace]
    else:
        assert drawn[:-1] == [t["open"] + 1 for t in trace[1:]]


def test_a_drive_moves_cell_by_cell(tmp_path):
    drive = polyplan.replan(data("movingai", "maps", "den312d.map"), (60, 12), (63, 76))
    assert gif_frames(polyplan.animate(drive, frames=FRAMES), tmp_path) == FRAMES


def test_a_potential_is_descended_in_its_world(tmp_path):
    world = polyplan.read_world(data("worlds", "sphere_world_polygons.json"))
    found = polyplan.potential(world)
    assert gif_frames(polyplan.animate(found, world=world, frames=FRAMES), tmp_path) == FRAMES
    with pytest.raises(polyplan.InputError, match="world="):
        polyplan.animate(found)


def test_search_frames_draw_a_plot_after_every_expansion(tmp_path):
    folder = tmp_path / "frames"
    result = polyplan.search_graph(SMALL, 0, 6, frames=folder)
    count = len(result["trace"])
    assert result["frames"] == [str(folder / f"step_{i:04d}.png") for i in range(1, count + 1)]
    assert sorted(p.name for p in folder.iterdir()) == [f"step_{i:04d}.png" for i in range(1, count + 1)]
    with Image.open(result["frames"][0]) as image:
        assert image.size[0] > 100
    plain = polyplan.search_graph(SMALL, 0, 6)
    assert "frames" not in plain and {k: v for k, v in result.items() if k != "frames"} == plain


def test_search_frames_refuse_large_graphs_and_long_searches(tmp_path):
    chain = [{"x": [i, 0], "neighbors": [i + 1] if i < 2000 else [], "neighbors_cost": [1] if i < 2000 else []}
             for i in range(2001)]
    with pytest.raises(polyplan.InputError, match="2001 vertices, more than the 2000"):
        polyplan.search_graph(chain, 0, 2000, frames=tmp_path / "chain")
    assert not (tmp_path / "chain").exists()
    result = polyplan.search_graph(SMALL, 0, 6)
    result["trace"] = result["trace"] * 1000
    with pytest.raises(polyplan.InputError, match="more than the 5000"):
        animation.search_frames(SMALL, result, tmp_path / "long")


def test_jupyter_shows_worlds_arms_and_plans_as_svg():
    plan = first_plan("worlds", "seed004.json")
    arm_plan = first_plan("arms", "two_link_points.json")
    for shown in (plan.problem, plan, arm_plan, arm_plan.problem):
        assert shown._repr_svg_().lstrip().startswith(("<svg", "<?xml"))
    # The arm alone: its obstacle points drawn, and no animation (it stands at its start).
    alone = arm_plan.problem._repr_svg_()
    assert alone.count("<circle") >= 24 and "<animate" not in alone


@pytest.mark.parametrize("arguments, message", [
    (dict(obj=42), "got int"),
    (dict(obj={"found": True}), "got dict"),
    (dict(obj=None), "got NoneType"),
])
def test_anything_else_is_refused_by_type(arguments, message):
    with pytest.raises(polyplan.InputError, match=message):
        polyplan.animate(**arguments)


def test_bad_options_are_refused():
    plan = first_plan("worlds", "seed004.json")
    with pytest.raises(polyplan.InputError, match="frames=0"):
        polyplan.animate(plan, frames=0)
    with pytest.raises(polyplan.InputError, match="what='tree'"):
        polyplan.animate(plan, what="tree")


def test_a_plan_is_labelled_with_its_options():
    assert plotting.plan_label(SimpleNamespace(planner="rrt", options={"goal_bias": "0.2", "seed": "3"})) == \
        "rrt goal_bias=0.2 seed=3"
    assert plotting.plan_label(SimpleNamespace(planner="rrt", options={})) == "rrt"
    assert plotting.plan_label(SimpleNamespace(planner="visibility")) == "visibility"


def test_a_plan_that_stopped_short_is_dashed_with_its_status():
    world = polyplan.read_world(data("worlds", "u_trap.json"))
    walked = SimpleNamespace(found=False, status="local_minimum", path=np.array([[10.0, 10.0], [10.0, 7.0]]),
                             planner="potential-field", query="start/goal", length=None, segments=None)
    _, ax = plt.subplots()
    plotting.draw_path(walked, ax, world)
    (line,) = [line for line in ax.get_lines() if line.get_label().startswith("potential-field")]
    assert line.get_linestyle() == "--" and line.get_label() == "potential-field start/goal: local_minimum"
    assert [line.get_marker() for line in ax.get_lines()].count("*") == 1  # the goal it did not reach
