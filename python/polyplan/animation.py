"""polyplan.animate and search_graph's frames: plans, searches, drives and descents as matplotlib
animations and pictures (imported only when asked for, as plotting is; they draw with its helpers)."""

import json
import math
import numbers
import os
from typing import List, NamedTuple, Optional

import numpy as np

from . import _polyplan, plotting
from ._arguments import path as _path, shown

MAX_FRAMES = 200  # a longer sequence of steps (expansions, cells driven) is shown every so many steps
MOTION_FRAMES = 100  # poses along a path, evenly spaced by distance
FIGURE = (6, 80)  # inches and dots per inch: 480 pixels square, which a GIF encodes twice as fast as plot's 700
MAX_FRAME_VERTICES = 2000  # search_graph(frames=...): beyond these, hours of PNGs nobody meant to write
MAX_FRAME_STEPS = 5000
MAX_ASKED_FRAMES = 10000  # animate(frames=...): beyond these, an animation nobody meant to draw
MAX_INTERVAL = 2**31 - 1  # milliseconds: a GUI timer's C int
MAX_GRAPH_FILE = 64 << 20  # bytes, as the program's readers (geometry/input_limits.hpp)
EDGE = "#d0d0d0"
VERTEX = "#b8b8b8"
CLOSED = plotting.EXPANDED
OPEN = "#30a060"
KNOWLEDGE_COLOURS = ["#d8d8d8", "#ffffff", "#404040"]  # a Drive's knowledge: unknown, free, blocked
CRITICAL_MARKERS = {"minimum": "v", "maximum": "^", "saddle": "X", "degenerate": "s"}


def animate(obj, ax=None, frames=None, interval=50, *, what="path", graph=None, world=None):
    """polyplan.animate: its docstring says what each kind of object becomes."""
    if not isinstance(what, str) or what not in ("path", "search"):
        raise _polyplan.InputError(f'animate: what={what!r}: expected "path" or "search"')
    if frames is not None:
        if _whole(frames) is None or not 1 <= _whole(frames) <= MAX_ASKED_FRAMES:
            raise _polyplan.InputError(f"animate: frames={_quoted(frames)}: expected a whole number in "
                                       f"[1, {MAX_ASKED_FRAMES}]")
        frames = _whole(frames)
    if not _is_real(interval) or not 0 <= interval <= MAX_INTERVAL:
        raise _polyplan.InputError(f"animate: interval={_quoted(interval)}: expected a number of milliseconds "
                                   f"in [0, {MAX_INTERVAL}]")
    if ax is not None and not _is_axes(ax):
        raise _polyplan.InputError(f"animate: ax: expected a matplotlib Axes, got {type(ax).__name__}")
    scene = _scene(obj, what, graph, world)
    ax = plotting.new_axes(ax, *FIGURE)
    update, steps = scene(obj, ax, frames)
    _pin_legend(ax)
    from matplotlib.animation import FuncAnimation
    return FuncAnimation(ax.figure, update, frames=list(steps), interval=interval, cache_frame_data=False)


def _pin_legend(ax):
    """Keep the legend where loc="best" put it in the first picture: seeking that place again takes
    half the drawing of every frame."""
    legend = ax.get_legend()
    if legend is None:
        return
    ax.figure.canvas.draw()
    corner = legend.get_window_extent().transformed(ax.transAxes.inverted()).p0
    handles, labels = ax.get_legend_handles_labels()
    ax.legend(handles, labels, loc="lower left", bbox_to_anchor=tuple(corner), borderaxespad=0, fontsize="small")


def _whole(value):
    """value as an int when it is a whole number (numpy's too; not a bool), else None."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        return None
    return int(value)


def _is_real(value):
    """Whether value is a finite real number (numpy's too; not a bool)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:  # an int beyond a double: finite, if huge
        return True


def _number(value):
    """value as a float when it is a real number (not a bool) that is not NaN, a double (inf
    allowed); else None."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        x = float(value)
    except (OverflowError, ValueError, TypeError):
        return None
    return None if math.isnan(x) else x


def _quoted(value):
    return shown(value, 80)


def _is_axes(ax):
    from matplotlib.axes import Axes
    return isinstance(ax, Axes)


def _scene(obj, what, graph, world):
    """The function that draws obj's scene on an Axes, scene(obj, ax, frames), returning update(step)
    and the steps to show."""
    if isinstance(obj, _polyplan.Plan):
        if what == "search":
            return _plan_search
        return _arm_motion if isinstance(obj.problem, _polyplan.Arm) else _world_motion
    if isinstance(obj, _polyplan.Drive):
        return _drive
    if isinstance(obj, dict) and "trace" in obj:
        return lambda result, ax, frames: _graph_search(result, graph, ax, frames)
    if isinstance(obj, dict) and "critical_points" in obj:
        return lambda result, ax, frames: _descent(result, world, ax, frames)
    raise _polyplan.InputError("animate: expected a Plan, a Drive, or a dict of search_graph or potential, got "
                               + type(obj).__name__)


def _shown(count, frames):
    """Which of `count` states to show: all of them, or `frames` (at most MAX_FRAMES) evenly
    spaced ones, the last among them."""
    wanted = min(count, frames or MAX_FRAMES)
    return np.linspace(count - 1, 0, wanted).round().astype(int)[::-1].tolist()


def _along(points, count, step_lengths):
    """`count` rows evenly spaced along the polyline through the rows of `points`, whose steps are
    `step_lengths` long; each column interpolated linearly."""
    travelled = np.concatenate([[0.0], np.cumsum(step_lengths)])
    at = np.linspace(0.0, travelled[-1], count)
    return np.column_stack([np.interp(at, travelled, column) for column in points.T])


def _path_of(plan):
    if not len(plan.path):
        raise _polyplan.InputError(f"animate: the plan {plan.planner} {plan.query} has no path ({plan.status}); "
                                   'animate(plan, what="search") shows its search')
    return plan.path


def _poses(plan, count):
    """`count` poses evenly spaced along the plan's path: a car's along its arcs; a rotating robot
    also turning on the spot, a turn as long as the way its farthest corner sweeps."""
    world, path = plan.problem, _path_of(plan)
    if plan.segments and world.car:
        total = sum(s["length"] for s in plan.segments)
        return plotting.car_poses(plan.segments, world.car["turning_radius"], np.linspace(0, total, count))
    steps = np.hypot(*np.diff(path[:, :2], axis=0).T)
    if path.shape[1] == 3:
        path = path.copy()
        path[:, 2] = np.unwrap(path[:, 2], period=360)  # from 350 to 10 degrees turns by 20, not back by 340
        radius = max((np.hypot(*ring.T).max() for ring in world.robot), default=0.0)
        steps = steps + radius * np.radians(np.abs(np.diff(path[:, 2])))
    return _along(path, count, steps)


def _world_motion(plan, ax, frames):
    """The robot (its polygon turned with its heading, or a dot) moving along the plan as plot draws it."""
    world = plan.problem
    poses = _poses(plan, frames or MOTION_FRAMES)
    plotting.plot(plan, ax)
    if world.robot:
        parts = [plotting.polygon(ax, ring, facecolor=plotting.ROBOT, edgecolor="black", lw=0.5, alpha=0.7, zorder=5)
                 for ring in plotting.placed_robot(world.robot, poses[0])]

        def update(i):
            for part, ring in zip(parts, plotting.placed_robot(world.robot, poses[i])):
                part.set_xy(ring)
    else:
        (dot,) = ax.plot([poses[0, 0]], [poses[0, 1]], "o", color=plotting.ROBOT, ms=9, zorder=5)

        def update(i):
            dot.set_data([poses[i, 0]], [poses[i, 1]])
    return update, range(len(poses))


def _arm_motion(plan, ax, frames):
    """The arm moving through the plan's configurations, its start and goal drawn faintly."""
    arm, path = plan.problem, _path_of(plan)
    if arm.limits is None:  # the joints turn freely: the short way round, as the planners' torus has it
        path = np.unwrap(path, axis=0)
    angles = _along(path, frames or MOTION_FRAMES, np.abs(np.diff(path, axis=0)).sum(axis=1))
    plotting.draw_arm_workspace(arm, ax)
    for end in (path[0], path[-1]):
        plotting.draw_arm(arm, end, ax, "#c8d4e8")
    line = plotting.draw_arm(arm, angles[0], ax, plotting.ROBOT)
    ax.set_aspect("equal")
    ax.set_title(f"{plotting.plan_label(plan)} {plan.query}: {plan.status}")

    def update(i):
        line.set_data(*arm.joint_positions(angles[i]).T)
    return update, range(len(angles))


def _plan_search(plan, ax, frames):
    """The configurations the plan's search expanded appearing in order (over the world, or in an
    arm's first two joint angles), then its path."""
    expanded, problem = plan.expanded, plan.problem
    if not len(expanded) or expanded.shape[1] < 2:
        raise _polyplan.InputError(f"animate: the plan {plan.planner} {plan.query} recorded no expanded "
                                   "configurations to show (plan with record=True, with a planner that expands "
                                   "some; an arm of two joints or more)")
    if isinstance(problem, _polyplan.Arm):
        ax.set_xlabel("joint 1 (radians)")
        ax.set_ylabel("joint 2 (radians)")
        finale = ax.plot(plan.path[:, 0], plan.path[:, 1], ".", color=plotting.PATH, zorder=3)
    else:
        plotting.draw_world(problem, ax, cobstacles=expanded.shape[1] == 2)
        finale = plotting.draw_path(plan, ax, problem)
    dots = ax.scatter(expanded[:, 0], expanded[:, 1], s=14, color=CLOSED, zorder=2)  # all of them: the limits
    ax.set_aspect("equal")
    ax.autoscale_view()
    count = len(expanded)

    def update(i):  # i + 1 expanded; i == count: all of them and the path
        dots.set_offsets(expanded[: i + 1, :2])
        for artist in finale:
            artist.set_visible(i == count)
        ax.set_title(f"{plotting.plan_label(plan)} {plan.query}: {min(i + 1, count)} of {count} expanded")
    return update, _shown(count + 1, frames)


class SearchSteps(NamedTuple):
    """What pictures of a search_graph result draw, found once: the vertices' positions (V, 2), the
    edges as segments (E, 2, 2), the trace, the vertices expanded in order, the index in the trace
    after which each vertex entered the open list and left it (len(trace): never), each vertex's
    backpointer when first expanded (-1: none) and whether the search is depth-first, the path,
    its cost and the goal (None when unknown)."""

    xy: np.ndarray
    edges: np.ndarray
    trace: list
    expanded: np.ndarray
    opened: np.ndarray
    closed: np.ndarray
    backpointers: np.ndarray
    depth_first: bool
    path: List[int]
    cost: Optional[float]
    goal: Optional[int]


def graph_vertices(graph):
    """The graph search_graph is given (a JSON file's path, or its list of dicts, numpy fields
    allowed) as a list of dicts of plain values, checked as the program's reader checks it: each
    vertex's "x" a point [x, y], its "neighbors" indices of vertices."""
    from . import _json_value

    if isinstance(graph, (str, os.PathLike)):
        graph = _graph_file(graph)
    vertices = _json_value(graph, "graph", exact=False)
    if not isinstance(vertices, list) or not all(isinstance(v, dict) and "x" in v for v in vertices):
        raise _polyplan.InputError('graph: expected a list of dicts {"x": [x, y], "neighbors": [...], ...}')
    count = len(vertices)
    for i, v in enumerate(vertices):
        x = v["x"]
        if not isinstance(x, list) or len(x) != 2 or not all(_is_real(c) for c in x):
            raise _polyplan.InputError(f"graph[{i}].x: expected a point [x, y], got {_quoted(x)}")
        neighbours = v.get("neighbors", [])
        if not isinstance(neighbours, list):
            raise _polyplan.InputError(f"graph[{i}].neighbors: expected a list of vertex indices, got "
                                       f"{_quoted(neighbours)}")
        for j, u in enumerate(neighbours):
            if not _is_real(u) or u != int(u) or not 0 <= u < count:
                raise _polyplan.InputError(f"graph[{i}].neighbors[{j}]: {_quoted(u)} is not a vertex "
                                           f"(0-based indices [0, {count}))")
        v["neighbors"] = [int(u) for u in neighbours]
    return vertices


def _graph_file(path):
    """The JSON of the graph file at `path`, refused (InputError naming it) as the program refuses
    a file: missing, a folder, larger than 64 MiB, not UTF-8, not JSON."""
    try:
        name = os.fspath(path)
    except TypeError as e:
        raise _polyplan.InputError(f"graph: expected a file's path or a list of dicts: {e}") from None
    if not isinstance(name, str):
        raise _polyplan.InputError("graph: expected a file's path (a str or a pathlib.Path), got "
                                   + type(name).__name__)
    shown = repr(name)[1:-1]
    if os.path.isdir(name):
        raise _polyplan.InputError(f"graph: {shown}: is a directory, not a file")
    try:
        with open(name, "rb") as f:
            text = f.read(MAX_GRAPH_FILE + 1)
    except (OSError, ValueError) as e:  # ValueError: a NUL in the name
        raise _polyplan.InputError(f"graph: {shown}: cannot open file ({getattr(e, 'strerror', None) or e})") from None
    if len(text) > MAX_GRAPH_FILE:
        raise _polyplan.InputError(f"graph: {shown}: larger than the supported 64 MiB")
    try:
        return json.loads(text.decode("utf-8"))
    except UnicodeDecodeError as e:
        raise _polyplan.InputError(f"graph: {shown}: not UTF-8 (byte {e.start})") from None
    except (ValueError, RecursionError) as e:
        raise _polyplan.InputError(f"graph: {shown}: not JSON: {str(e)[:200]}") from None


def search_steps(graph, result, goal=None):
    """The SearchSteps of search_graph's `result` on `graph` (what search_graph was given)."""
    vertices = graph_vertices(graph)
    trace, path, cost = _checked_result(result, len(vertices))
    xy = np.array([v["x"] for v in vertices], dtype=float).reshape(-1, 2)
    neighbours = [v["neighbors"] for v in vertices]
    pairs = sorted({(min(a, b), max(a, b)) for a, ns in enumerate(neighbours) for b in ns})
    expanded = np.array([t["vertex"] for t in trace], dtype=int)
    opened, closed = _open_intervals(neighbours, expanded)
    backpointers = np.full(len(vertices), -1)
    for t in reversed(trace):
        backpointers[t["vertex"]] = -1 if t["backpointer"] is None else t["backpointer"]
    depth_first = result.get("method") == "dfs"
    if depth_first and any(isinstance(t["open"], int) for t in trace):
        _acyclic(backpointers)  # the stack drawn is the way back from the vertex expanded
    if goal is not None:
        goal = _whole(goal)
        if goal is None or not 0 <= goal < len(vertices):
            raise _polyplan.InputError(f"goal: not a vertex of graph (0-based indices [0, {len(vertices)}))")
    goal = goal if goal is not None else (path[-1] if path else None)
    return SearchSteps(xy, xy[np.array(pairs, dtype=int).reshape(-1, 2)], trace, expanded, opened, closed,
                       backpointers, depth_first, path, cost, goal)


def _checked_result(result, count):
    """The trace (one dict per expansion: step, vertex, g, h, f, backpointer, open), path and cost of
    a search_graph result, checked against a graph of `count` vertices, as plain values; an
    InputError naming what is wrong for anything else (a result not from search_graph, or from
    another graph)."""
    what = "search_graph's result"
    if not isinstance(result, dict):
        raise _polyplan.InputError(f"{what}: expected the dict search_graph returns, got {type(result).__name__}")

    def vertex(value, where):
        index = _whole(value)
        if index is None or not 0 <= index < count:
            raise _polyplan.InputError(f"{what}: {where}: {_quoted(value)} is not a vertex of graph, which has "
                                       f"{count} vertices (0-based indices [0, {count}))")
        return index

    trace = result.get("trace")
    if not isinstance(trace, (list, tuple)) or not trace:
        raise _polyplan.InputError(f"{what}: its trace is empty" if not trace and isinstance(trace, (list, tuple))
                                   else f"{what}: trace: expected a non-empty list of dicts, got "
                                   f"{type(trace).__name__}")
    checked = []
    for i, t in enumerate(trace):
        where = f"trace[{i}]"
        if not isinstance(t, dict):
            raise _polyplan.InputError(f"{what}: {where}: expected a dict (step, vertex, g, h, f, backpointer, open), "
                                       f"got {type(t).__name__}")
        missing = [k for k in ("step", "vertex", "g", "h", "f", "backpointer", "open") if k not in t]
        if missing:
            raise _polyplan.InputError(f"{what}: {where}: missing {', '.join(missing)}")
        line = dict(t, vertex=vertex(t["vertex"], where + ".vertex"),
                    backpointer=None if t["backpointer"] is None else vertex(t["backpointer"], where + ".backpointer"))
        for key in ("g", "h", "f"):
            line[key] = _number(t[key])
            if line[key] is None:
                raise _polyplan.InputError(f"{what}: {where}.{key}: expected a number, got {_quoted(t[key])}")
        step = _whole(t["step"])
        if step is None or step < 0:
            raise _polyplan.InputError(f"{what}: {where}.step: expected a whole number >= 0, got "
                                       f"{_quoted(t['step'])}")
        line["step"] = step
        given = t["open"]
        if _whole(given) is not None:
            line["open"] = _whole(given)
        elif isinstance(given, (list, tuple, np.ndarray)):
            line["open"] = [vertex(u, f"{where}.open[{j}]") for j, u in enumerate(np.asarray(given).ravel().tolist())]
        else:
            raise _polyplan.InputError(f"{what}: {where}.open: expected the open list's size or its vertices, got "
                                       f"{_quoted(given)}")
        checked.append(line)
    path = result.get("path", [])
    if path is None:
        path = []
    if not isinstance(path, (list, tuple, np.ndarray)):
        raise _polyplan.InputError(f"{what}: path: expected a list of vertex indices, got {_quoted(path)}")
    path = [vertex(v, f"path[{i}]") for i, v in enumerate(list(path))]
    cost = result.get("cost")
    if cost is not None and _number(cost) is None:
        raise _polyplan.InputError(f"{what}: cost: expected a number or None, got {_quoted(cost)}")
    return checked, path, None if cost is None else _number(cost)


def _acyclic(backpointers):
    """Refuses backpointers that lead round in a circle (a depth-first search's stack is the way
    back from the vertex expanded to the start)."""
    state = np.zeros(len(backpointers), dtype=np.int8)  # 0 unseen, 1 on the way being followed, 2 done
    for v in range(len(backpointers)):
        way = []
        while v >= 0 and state[v] == 0:
            state[v] = 1
            way.append(v)
            v = backpointers[v]
        if v >= 0 and state[v] == 1:
            raise _polyplan.InputError(f"search_graph's result: trace: the backpointers go round in a circle "
                                       f"through vertex {v}")
        state[way] = 2


def _open_intervals(neighbours, expanded):
    """For each vertex, the trace index after which it was in the open list (the start from before
    the first; any other once a neighbour was expanded: each search but the depth-first one puts
    every vertex it reaches that is not closed in its open list) and the index at which it was
    first expanded."""
    never = len(expanded)
    opened = np.full(len(neighbours), never)
    closed = np.full(len(neighbours), never)
    np.minimum.at(closed, expanded, np.arange(never))
    opened[expanded[0]] = -1
    for i, v in enumerate(expanded):
        for u in neighbours[v]:
            opened[u] = min(opened[u], i)
    return opened, closed


def _open_after(steps, i):
    """The vertices in the open list after the expansion trace[i]: the trace's own list when it has
    one; else (a trace holding the open list's size) those reached and not yet expanded, or for a
    depth-first search its stack, the vertices from the start to the one expanded."""
    given = steps.trace[i]["open"]
    if isinstance(given, (list, tuple, np.ndarray)):
        return np.asarray(given, dtype=int)
    if steps.depth_first:
        stack, v = [], steps.backpointers[steps.expanded[i]]
        while v >= 0:
            stack.append(v)
            v = steps.backpointers[v]
        return np.array(stack, dtype=int)
    return np.flatnonzero((steps.opened <= i) & (steps.closed > i))


def draw_search_state(ax, steps, i):
    """Draw on ax (cleared first) the search of `steps` (a SearchSteps) after the expansion
    trace[i]: the edges, the closed vertices, the open list and the vertex expanded, its step,
    vertex, g, h and f in the title; i == len(trace): the end, with the path."""
    from matplotlib.collections import LineCollection

    ax.clear()
    count = len(steps.trace)
    last = min(i, count - 1)
    ax.add_collection(LineCollection(steps.edges, colors=EDGE, linewidths=0.8, zorder=1))
    ax.scatter(*steps.xy.T, s=10, color=VERTEX, zorder=2)
    ax.scatter(*steps.xy[steps.expanded[: last + 1]].T, s=28, color=CLOSED, zorder=3, label="closed")
    ax.scatter(*steps.xy[_open_after(steps, last)].T, s=28, color=OPEN, zorder=3, label="open")
    if i < count:
        t = steps.trace[i]
        ax.scatter(*steps.xy[t["vertex"]], s=140, facecolor="none", edgecolor="black", lw=1.5, zorder=4,
                   label="expanded now")
        ax.set_title(f"step {t['step']}: vertex {t['vertex']}   g {t['g']:.4g}   h {t['h']:.4g}   f {t['f']:.4g}")
    elif steps.path:
        ax.plot(*steps.xy[steps.path].T, color=plotting.PATH, lw=2.5, zorder=4, label="path")
        cost = "" if steps.cost is None else f" of cost {steps.cost:.4g}"
        ax.set_title(f"path{cost} after {count} expansions")
    else:
        ax.set_title(f"no path after {count} expansions")
    ax.plot(*steps.xy[steps.expanded[0]], "o", color="black", ms=8, zorder=5, label="start")
    if steps.goal is not None:
        ax.plot(*steps.xy[steps.goal], "*", color="black", ms=14, zorder=5, label="goal")
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.legend(loc="best", fontsize="small")


def _graph_search(result, graph, ax, frames):
    """search_graph's search expansion by expansion, then its path."""
    if graph is None:
        raise _polyplan.InputError("animate: a search_graph result needs its graph's vertex positions: "
                                   "animate(result, graph=...), the graph search_graph was given")
    steps = search_steps(graph, result)

    def update(i):
        draw_search_state(ax, steps, i)
    return update, _shown(len(steps.trace) + 1, frames)


def search_frames(graph, result, folder, goal=None):
    """search_graph(frames=folder): one PNG per expansion, folder/step_0001.png, ... (created or
    overwritten) drawn by draw_search_state; returns their paths. Refuses a graph of more than
    MAX_FRAME_VERTICES vertices or a trace of more than MAX_FRAME_STEPS steps."""
    from matplotlib.figure import Figure

    folder = _path(folder, "search_graph: frames", utf8=False)
    vertices = graph_vertices(graph)
    if len(vertices) > MAX_FRAME_VERTICES:
        raise _polyplan.InputError(f"search_graph: frames: the graph has {len(vertices)} vertices, more than the "
                                   f"{MAX_FRAME_VERTICES} drawn a frame per expansion")
    steps = search_steps(vertices, result, goal)
    if len(steps.trace) > MAX_FRAME_STEPS:
        raise _polyplan.InputError(f"search_graph: frames: the search took {len(steps.trace)} steps, more than "
                                   f"the {MAX_FRAME_STEPS} drawn a frame each")
    shown = repr(folder)[1:-1]
    try:
        os.makedirs(folder, exist_ok=True)
    except (OSError, ValueError) as e:
        raise _polyplan.InputError(f"search_graph: frames: {shown}: cannot make the folder "
                                   f"({getattr(e, 'strerror', None) or e})") from None
    figure = Figure(figsize=(7, 7))  # no pyplot: nothing to show, nothing left open
    ax = figure.add_subplot()
    written = []
    for i, t in enumerate(steps.trace):
        draw_search_state(ax, steps, i)
        written.append(os.path.join(folder, f"step_{t['step']:04d}.png"))
        try:
            figure.savefig(written[-1])
        except OSError as e:
            raise _polyplan.InputError(f"search_graph: frames: {repr(written[-1])[1:-1]}: cannot write "
                                       f"({e.strerror or e})") from None
    return written


def _drive(drive, ax, frames):
    """The robot driving cell by cell over what it knew of the map at the end; a cross where it replanned."""
    from matplotlib.colors import to_rgba_array

    cells = np.array(drive.traversed, dtype=float).reshape(-1, 2)
    # Step j planned from cell j of the drive; the replans among them, by the cell they were made at.
    replans = np.array([j for j, s in enumerate(drive.steps) if s["replanned"]], dtype=int)
    # Row 0 on top, as in the map file; cell (x, y) centred on (x, y).
    ax.imshow(plotting.image_bytes(to_rgba_array(KNOWLEDGE_COLOURS)[drive.knowledge]), interpolation="nearest")
    (trail,) = ax.plot([], [], color=plotting.PATH, lw=1.5, zorder=3)
    (robot,) = ax.plot([], [], "o", color=plotting.ROBOT, ms=7, zorder=5)
    marks = ax.scatter(*cells[replans].T, marker="x", color="black", s=30, zorder=4, label="replanned")
    if drive.last_plan:
        ax.plot(*drive.last_plan[-1], "*", color=plotting.PATH, ms=14, zorder=5, label="goal")
    ax.legend(loc="best", fontsize="small")

    def update(i):
        trail.set_data(*cells[: i + 1].T)
        robot.set_data([cells[i, 0]], [cells[i, 1]])
        done = replans[replans <= i]
        marks.set_offsets(cells[done])
        ax.set_title(f"{drive.algorithm}: move {i} of {len(cells) - 1}, {len(done)} replans")
    return update, _shown(len(cells), frames)


def _descent(result, world, ax, frames):
    """The potential-field planner descending with the result's parameters over the field (plan
    records it), the result's critical points marked."""
    from . import planner

    if world is None:
        raise _polyplan.InputError("animate: polyplan.potential's result holds critical points, not a path: "
                                   "animate(result, world=w), w the world it was computed for, follows the "
                                   "potential-field planner down with its parameters")
    if not isinstance(world, _polyplan.World):
        raise _polyplan.InputError(f"animate: world: expected the polyplan.World the potential was computed for, "
                                   f"got {type(world).__name__}")
    parameters, critical = result.get("parameters"), result["critical_points"]
    if not isinstance(parameters, dict) or not all(isinstance(k, str) for k in parameters):
        raise _polyplan.InputError("animate: polyplan.potential's result: parameters: expected the dict of the "
                                   f"potential-field planner's options it returns, got {_quoted(parameters)}")
    if not isinstance(critical, (list, tuple)):
        raise _polyplan.InputError("animate: polyplan.potential's result: critical_points: expected a list of dicts "
                                   f"{{at, kind}}, got {_quoted(critical)}")
    for i, p in enumerate(critical):
        at = p.get("at") if isinstance(p, dict) else None
        point = isinstance(at, (list, tuple, np.ndarray)) and len(at) == 2 and all(_number(c) is not None for c in at)
        if not point or not isinstance(p.get("kind"), str):
            raise _polyplan.InputError(f"animate: polyplan.potential's result: critical_points[{i}]: expected a dict "
                                       f"{{at: [x, y], kind: str}}, got {_quoted(p)}")
    plan = planner("potential-field", world, **parameters).plan(record=True)
    update, steps = _world_motion(plan, ax, frames)
    for kind, marker in CRITICAL_MARKERS.items():
        points = np.array([p["at"] for p in critical if p["kind"] == kind], dtype=float).reshape(-1, 2)
        if len(points):
            ax.scatter(*points.T, marker=marker, s=70, color="white", edgecolor="black", zorder=6, label=kind)
    ax.legend(loc="best", fontsize="small")
    return update, steps
