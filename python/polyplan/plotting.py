"""polyplan.plot: plans drawn with matplotlib (imported only when plot is called)."""

import math

import numpy as np

from . import _polyplan

OBSTACLE = "#555555"
COBSTACLE = "#e8a0a0"
ROADMAP = "#7aa6d6"
EXPANDED = "#f0a030"
PATH = "#c01020"
ROBOT = "#2060c0"
CELL_COLOURS = ["#ffffff00", "#ffffff00", "#b0b0b0", "#60a060"]  # not evaluated, free, blocked, ridge


def plot(r, ax=None):
    import matplotlib.pyplot as plt

    plans, problem = _plans_and_problem(r)
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 7))
    if isinstance(problem, _polyplan.Arm):
        _plot_arm(problem, plans, ax)
    else:
        _plot_world(problem, plans, ax)
    ax.set_aspect("equal")
    return ax


def _plans_and_problem(r):
    if isinstance(r, (_polyplan.World, _polyplan.Arm)):
        return [], r
    plans = [r] if isinstance(r, _polyplan.Plan) else list(r)
    if not plans or not all(isinstance(p, _polyplan.Plan) for p in plans):
        raise _polyplan.InputError("plot: expected a Plan, a list of Plan, a World or an Arm")
    problem = plans[0].problem
    if any(p.problem is not problem for p in plans):
        raise _polyplan.InputError("plot: the plans are of different problems")
    return plans, problem


def _polygon(ax, ring, **style):
    from matplotlib.patches import Polygon
    ax.add_patch(Polygon(ring, closed=True, **style))


def _plot_world(world, plans, ax):
    if world.bounds is not None:
        xmin, ymin, xmax, ymax = (float(v) for v in world.bounds)
        ax.plot([xmin, xmax, xmax, xmin, xmin], [ymin, ymin, ymax, ymax, ymin], color="black", lw=1)
    translating = any(p.path.shape[1] == 2 for p in plans) or not plans
    if world.robot and translating:
        for ring in _polyplan.cspace(world).obstacles:
            _polygon(ax, ring, facecolor=COBSTACLE, edgecolor="none", label=None)
    for ring in world.obstacles:
        _polygon(ax, ring, facecolor=OBSTACLE, edgecolor="black", lw=0.5)
    for i, p in enumerate(plans):
        _plot_record(p, ax)
        _plot_path(p, ax, world, _colour(i, len(plans)))
    ax.autoscale_view()


def _colour(i, count):
    """The i-th plan's colour: the path colour for one plan, matplotlib's cycle for several."""
    return PATH if count == 1 else f"C{i % 10}"


def _plot_record(p, ax):
    """What the plan recorded: cells, the roadmap or tree, the expanded configurations."""
    from matplotlib.collections import LineCollection
    from matplotlib.colors import ListedColormap

    if p.cells is not None and not p.cells.wraps:
        c = p.cells
        rows, columns = c.states.shape
        extent = (c.x0, c.x0 + columns * c.cell_width, c.y0, c.y0 + rows * c.cell_height)
        ax.imshow(c.states, origin="lower", extent=extent, cmap=ListedColormap(CELL_COLOURS), vmin=0, vmax=3,
                  interpolation="nearest", zorder=0)
    for cell in p.decomposition or []:
        _polygon(ax, cell[:, :2], facecolor="none", edgecolor="#9ab", lw=0.4)
    if p.graph is not None and len(p.graph.edges):
        v = p.graph.vertices[:, :2]
        ax.add_collection(LineCollection(v[p.graph.edges], colors=ROADMAP, linewidths=0.5, zorder=1))
    if len(p.expanded):
        ax.scatter(p.expanded[:, 0], p.expanded[:, 1], s=6, color=EXPANDED, zorder=2)


def _query_ends(world, name):
    """The start and goal (x, y) of the world's query called `name`, as floats."""
    for query, start, goal in world.queries:
        if query == name:
            return [float(v) for v in start[:2]], [float(v) for v in goal[:2]]
    return None


def _plot_path(p, ax, world, colour=PATH):
    if not p.found:  # its start and goal, and why it has no path, in the legend
        ends = _query_ends(world, p.query)
        if ends is not None:
            (sx, sy), (gx, gy) = ends
            ax.plot([sx], [sy], "o", color=colour, zorder=4, label=f"{p.planner} {p.query}: {p.status}")
            ax.plot([gx], [gy], "*", color=colour, ms=12, zorder=4)
        ax.legend(loc="best", fontsize="small")
        return
    path = p.path
    ax.plot(path[:, 0], path[:, 1], color=colour, lw=2, zorder=3, label=f"{p.planner} {p.query}: {p.length:.4g}")
    ax.plot(path[0, 0], path[0, 1], "o", color=colour, zorder=4)
    ax.plot(path[-1, 0], path[-1, 1], "*", color=colour, ms=12, zorder=4)
    if path.shape[1] == 3 and world.robot:  # the rotating robot at some poses along the path
        for x, y, theta in path[:: max(1, len(path) // 12)]:
            c, s = math.cos(math.radians(theta)), math.sin(math.radians(theta))
            for part in world.robot:
                placed = part @ np.array([[c, s], [-s, c]]) + (x, y)
                _polygon(ax, placed, facecolor="none", edgecolor=ROBOT, lw=0.6, zorder=3)
    ax.legend(loc="best", fontsize="small")


def _plot_arm(arm, plans, ax):
    from matplotlib import cm

    for ring in arm.obstacles:
        _polygon(ax, ring, facecolor=OBSTACLE, edgecolor="black", lw=0.5)
    if len(arm.points):
        ax.scatter(arm.points[:, 0], arm.points[:, 1], s=8, color=OBSTACLE)
    reach = sum(arm.links)
    for p in plans:
        if not p.found:
            continue
        path = p.path
        shown = path[:: max(1, len(path) // 16)].tolist() + [path[-1].tolist()]
        for i, q in enumerate(shown):
            joints = arm.joint_positions(q)
            ax.plot(joints[:, 0], joints[:, 1], "-o", ms=2, lw=max(1.5, 2 * arm.link_width),
                    color=cm.Blues(0.3 + 0.7 * i / max(1, len(shown) - 1)), zorder=3)
        ax.set_title(f"{p.planner} {p.query}: {p.status}")
    ax.set_xlim(-reach * 1.05, reach * 1.05)
    ax.set_ylim(-reach * 1.05, reach * 1.05)
