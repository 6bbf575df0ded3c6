"""polyplan.plot: plans drawn with matplotlib (imported only when plot is called). The drawing
helpers without an underscore are polyplan.animate's too (animation.py)."""

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
CAR_CURVE_POSES = 400  # a car's drawn path: poses evenly spaced along its arcs, besides each segment's ends


def plot(r, ax=None):
    plans, problem = _plans_and_problem(r)
    ax = new_axes(ax)
    if isinstance(problem, _polyplan.Arm):
        _plot_arm(problem, plans, ax)
    else:
        _plot_world(problem, plans, ax)
    ax.set_aspect("equal")
    return ax


def new_axes(ax=None, inches=7, dpi=100):
    """ax, or the Axes of a new square figure."""
    import matplotlib.pyplot as plt
    from matplotlib.axes import Axes
    if ax is not None:
        if not isinstance(ax, Axes):
            raise _polyplan.InputError(f"ax: expected a matplotlib Axes, got {type(ax).__name__}")
        return ax
    _, ax = plt.subplots(figsize=(inches, inches), dpi=dpi)
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


def polygon(ax, ring, **style):
    """A closed polygon through the rows of `ring`, added to ax; returns the patch."""
    from matplotlib.patches import Polygon
    return ax.add_patch(Polygon(ring, closed=True, **style))


def draw_world(world, ax, cobstacles=True):
    """The world's bounds, obstacles, discs and walls; with cobstacles, the C-obstacles of its robot
    translating (of a polygon world's robot: a world with discs or walls draws its own things only)."""
    from matplotlib.patches import Circle
    if world.bounds is not None:
        xmin, ymin, xmax, ymax = (float(v) for v in world.bounds)
        ax.plot([xmin, xmax, xmax, xmin, xmin], [ymin, ymin, ymax, ymax, ymin], color="black", lw=1)
    if world.disc_bounds is not None:
        x, y, r = (float(v) for v in world.disc_bounds)
        ax.add_patch(Circle((x, y), r, facecolor="none", edgecolor="black", lw=1))
    round_world = len(world.discs) or world.walls or world.disc_bounds is not None or world.robot_disc is not None
    if (world.robot or world.robot_disc is not None) and cobstacles:
        if round_world:
            for core in _polyplan.cspace(world).obstacles:
                _draw_grown_core(ax, core)
        else:
            for ring in _polyplan.cspace(world).obstacles:
                polygon(ax, ring, facecolor=COBSTACLE, edgecolor="none", label=None)
    for ring in world.obstacles:
        polygon(ax, ring, facecolor=OBSTACLE, edgecolor="black", lw=0.5)
    for x, y, r in world.discs:
        ax.add_patch(Circle((x, y), r, facecolor=OBSTACLE, edgecolor="black", lw=0.5))
    for wall in world.walls:
        ax.plot(wall[:, 0], wall[:, 1], color="black", lw=2.5, solid_capstyle="butt")


def _draw_grown_core(ax, core):
    """A round world's C-obstacle (polyplan.cspace(world).obstacles): its core — a point, a wall or a
    polygon — grown by its radius, drawn as the core, a disc round each of its points and a band
    either side of each of its edges, all in one colour: their union is the grown core."""
    from matplotlib.patches import Circle
    style = dict(facecolor=COBSTACLE, edgecolor="none")
    r = float(core.radius)
    points = np.asarray(core.points, dtype=float)
    if core.kind == "polygon":
        polygon(ax, points, **style)
    if r <= 0:
        return
    for x, y in points:
        ax.add_patch(Circle((x, y), r, **style))
    closed = core.kind == "polygon"
    for ring in [points] + ([np.asarray(h, dtype=float) for h in core.holes] if closed else []):
        ends = zip(ring, np.roll(ring, -1, axis=0)) if closed else zip(ring[:-1], ring[1:])
        for a, b in ends:
            d = b - a
            n = np.array([-d[1], d[0]]) * (r / np.hypot(*d))
            polygon(ax, np.array([a + n, b + n, b - n, a - n]), **style)


def _plot_world(world, plans, ax):
    # The C-obstacles are those of the robot translating: a rotating robot's or a car's change as it turns.
    draw_world(world, ax, cobstacles=any(p.path.shape[1] == 2 for p in plans) or not plans)
    for i, p in enumerate(plans):
        _plot_record(p, ax)
        draw_path(p, ax, world, _colour(i, len(plans)))
    ax.autoscale_view()


def _colour(i, count):
    """The i-th plan's colour: the path colour for one plan, matplotlib's cycle for several."""
    return PATH if count == 1 else f"C{i % 10}"


def _plot_record(p, ax):
    """What the plan recorded: cells, the roadmap or tree, the expanded configurations."""
    from matplotlib.collections import LineCollection

    if p.cells is not None and not p.cells.wraps:
        _plot_cells(p.cells, ax)
    for cell in p.decomposition or []:
        polygon(ax, cell[:, :2], facecolor="none", edgecolor="#9ab", lw=0.4)
    if p.graph is not None and len(p.graph.edges):
        v = p.graph.vertices[:, :2]
        ax.add_collection(LineCollection(v[p.graph.edges], colors=ROADMAP, linewidths=0.5, zorder=1))
    if len(p.expanded):
        ax.scatter(p.expanded[:, 0], p.expanded[:, 1], s=6, color=EXPANDED, zorder=2)


def _plot_cells(c, ax):
    """The cells' states and, when the planner gives a value per cell (a potential, a distance), its
    heat map over the free and ridge cells, as the program's pictures show it."""
    import matplotlib
    from matplotlib.colors import Normalize, to_rgba_array

    rows, columns = c.states.shape
    extent = (c.x0, c.x0 + columns * c.cell_width, c.y0, c.y0 + rows * c.cell_height)
    rgba = to_rgba_array(CELL_COLOURS)[c.states]
    heated = (c.states == 1) | (c.states == 3)
    if c.values is not None and heated.any():
        values = c.values[heated]
        rgba[heated] = matplotlib.colormaps["viridis"](Normalize(values.min(), values.max())(values), alpha=0.6)
    ax.imshow(image_bytes(rgba), origin="lower", extent=extent, interpolation="nearest", zorder=0)


def image_bytes(rgba):
    """An RGBA image of floats in [0, 1] as bytes, which matplotlib redraws four times faster (an
    animation redraws it in every frame)."""
    return (rgba * 255).round().astype(np.uint8)


def _query_ends(world, name):
    """The start and goal (x, y) of the world's query called `name`, as floats."""
    for query, start, goal in world.queries:
        if query == name:
            return [float(v) for v in start[:2]], [float(v) for v in goal[:2]]
    return None


def plan_label(p):
    """The planner's name and the options the plan was planned with that differ from their defaults
    ("rrt goal_bias=0.2 seed=3"), for a legend."""
    options = getattr(p, "options", None) or {}
    return " ".join([p.planner] + [f"{name}={value}" for name, value in options.items()])


def draw_path(p, ax, world, colour=PATH):
    """The plan's path from start (o) to goal (*), labelled in the legend with its length; a rotating
    robot or a car drawn at some poses along it. A plan that stopped short (not found, with the path
    it walked) is dashed, ends at x and has its status in the label; a plan without a path: its
    query's start and goal, with its status. Returns the artists drawn."""
    path = drawn_path(p, world)
    ends = _query_ends(world, p.query)
    label = f"{plan_label(p)} {p.query}: " + (f"{p.length:.4g}" if p.found else p.status)
    artists = []
    if len(path):
        artists += ax.plot(path[:, 0], path[:, 1], color=colour, lw=2, ls="-" if p.found else "--", zorder=3,
                           label=label)
        artists += ax.plot(path[0, 0], path[0, 1], "o", color=colour, zorder=4)
        artists += ax.plot(path[-1, 0], path[-1, 1], "*" if p.found else "x", color=colour, ms=12, zorder=4)
    elif ends is not None:
        artists += ax.plot(*ends[0], "o", color=colour, zorder=4, label=label)
    if not p.found and ends is not None:
        artists += ax.plot(*ends[1], "*", color=colour, ms=12, zorder=4)
    if path.shape[1] == 3 and world.robot:  # the rotating robot or the car at some poses along the path
        for pose in path[:: max(1, len(path) // 12)]:
            artists += [polygon(ax, ring, facecolor="none", edgecolor=ROBOT, lw=0.6, zorder=3)
                        for ring in placed_robot(world.robot, pose)]
    ax.legend(loc="best", fontsize="small")
    return artists


def drawn_path(p, world):
    """The plan's path as drawn: a car's through its arcs, sampled finely; a path of tangents and
    arcs (Plan.pieces) through its arcs likewise; others' as planned."""
    pieces = getattr(p, "pieces", None)  # a Drive (polyplan.replan) has none
    if pieces:
        return _pieces_path(pieces)
    if not (p.segments and world.car):
        return p.path
    lengths = [s["length"] for s in p.segments]
    distances = np.union1d(np.linspace(0, sum(lengths), CAR_CURVE_POSES), np.cumsum([0] + lengths))
    return car_poses(p.segments, world.car["turning_radius"], distances)


def _pieces_path(pieces):
    """Segments and arcs (Plan.pieces) as one polyline, each arc through a point every 2 degrees."""
    points = [pieces[0]["from"]]
    for piece in pieces:
        if piece["kind"] == "arc":
            (cx, cy), (x, y) = piece["centre"], piece["from"]
            turn = piece["length"] / piece["radius"] * (1 if piece["turn"] == "ccw" else -1)
            start = math.atan2(y - cy, x - cx)
            for t in np.linspace(0, 1, max(2, int(abs(math.degrees(turn)) / 2) + 1))[1:-1]:
                points.append((cx + piece["radius"] * math.cos(start + t * turn),
                               cy + piece["radius"] * math.sin(start + t * turn)))
        points.append(piece["to"])
    return np.array(points, dtype=float)


def car_poses(segments, radius, distances):
    """The car's poses (x, y, degrees) after driving each of `distances` (sorted, from 0 to the
    segments' total length) along its segments, turning with `radius`."""
    starts = np.cumsum([0] + [s["length"] for s in segments[:-1]])
    which = np.clip(np.searchsorted(starts, distances, side="right") - 1, 0, len(segments) - 1)
    return np.array([_driven(segments[i], radius, d - starts[i]) for i, d in zip(which, distances)])


def _driven(segment, radius, distance):
    """The pose after driving `distance` along one segment from its start: straight, or on a circle of
    `radius` to the left (L) or right (R) of the heading; in reverse gear backwards."""
    x, y, degrees = segment["start"]
    heading, d = math.radians(degrees), distance * segment["gear"]
    curvature = {"L": 1, "S": 0, "R": -1}[segment["steer"]] / radius
    if curvature == 0:
        return x + d * math.cos(heading), y + d * math.sin(heading), degrees
    after = heading + curvature * d
    return (x + (math.sin(after) - math.sin(heading)) / curvature,
            y - (math.cos(after) - math.cos(heading)) / curvature, math.degrees(after))


def placed_robot(robot, pose):
    """The robot's parts (rings in its own frame) at pose (x, y) or (x, y, degrees)."""
    x, y = pose[0], pose[1]
    theta = math.radians(pose[2]) if len(pose) > 2 else 0.0
    c, s = math.cos(theta), math.sin(theta)
    return [part @ np.array([[c, s], [-s, c]]) + (x, y) for part in robot]


def draw_arm_workspace(arm, ax):
    """The arm's obstacles and obstacle points, in a square the arm reaches across."""
    for ring in arm.obstacles:
        polygon(ax, ring, facecolor=OBSTACLE, edgecolor="black", lw=0.5)
    if len(arm.points):
        ax.scatter(arm.points[:, 0], arm.points[:, 1], s=8, color=OBSTACLE)
    reach = sum(arm.links)
    ax.set_xlim(-reach * 1.05, reach * 1.05)
    ax.set_ylim(-reach * 1.05, reach * 1.05)


def draw_arm(arm, angles, ax, colour):
    """The arm at joint angles `angles`: its links and joints; returns the line, to move it."""
    joints = arm.joint_positions(angles)
    (line,) = ax.plot(joints[:, 0], joints[:, 1], "-o", ms=2, lw=max(1.5, 2 * arm.link_width), color=colour,
                      zorder=3)
    return line


def _plot_arm(arm, plans, ax):
    from matplotlib import cm

    draw_arm_workspace(arm, ax)
    for p in plans:
        if not p.found:
            continue
        path = p.path
        shown = path[:: max(1, len(path) // 16)].tolist() + [path[-1].tolist()]
        for i, q in enumerate(shown):
            draw_arm(arm, q, ax, cm.Blues(0.3 + 0.7 * i / max(1, len(shown) - 1)))
        ax.set_title(f"{plan_label(p)} {p.query}: {p.status}")
