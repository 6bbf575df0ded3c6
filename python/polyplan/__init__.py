"""polyplan: exact motion planning in polygon worlds.

Read a problem, build a planner of the registry for it, and ask it for plans::

    import polyplan
    w = polyplan.read_world("data/worlds/seed004.json")
    p = polyplan.planner("visibility", w, search="astar")    # built once
    r = p.plan(start=(2, 3), goal=(95, 80))                  # one query
    r.found, r.status, r.length, r.path                      # path: an (N, 2) float64 array
    polyplan.plot(r)                                         # matplotlib

Geometry is exact: coordinates given as int, fractions.Fraction or decimal strings ("0.1") are
their exact values; a float is the exact value of that double. Every collision and every path is
decided with exact arithmetic, and a Plan's path is certified free.

Bad input (a file, a value, a planner or an option polyplan refuses) raises polyplan.InputError, a
ValueError carrying the message the `polyplan` program prints. A RuntimeError is a bug.

Planning, building a C-space and drawing release the GIL: threads planning on different problems
run in parallel. polyplan.planners() lists every planner with its options.
"""

import decimal as _decimal
import fractions as _fractions
import json as _json
import math as _math
import numbers as _numbers
from typing import List, NamedTuple, Optional

from ._polyplan import (  # noqa: F401 (the public names)
    Arm,
    CSpace,
    Drive,
    InputError,
    Plan,
    Planner,
    RoundCSpace,
    World,
    check,
    cspace,
    grid,
    ik,
    potential,
    read_arm,
    read_world,
    replan,
    scen,
    Space,
    space,
    steer,
    svg,
)
from . import _polyplan
from .cluster import ExperimentInterrupted
from .experiment import Experiment, Results

__all__ = [
    "Arm", "CSpace", "Cells", "Drive", "Experiment", "ExperimentInterrupted", "FreeComponent", "Graph", "InputError", "Option", "Plan", "Planner",
    "PlannerInfo", "RoundCore", "RoundCSpace", "World", "animate", "check", "cspace", "grid", "ik", "plan", "planner", "planners", "plot", "potential",
    "read_arm", "read_world", "replan", "Results", "scen", "search_graph", "Space", "space", "steer", "svg",
]


class Option(NamedTuple):
    """One option of a planner: polyplan.planner(name, problem, <name_with_underscores>=value).

    range: for a number, (min, max, min_open, max_open) (an unbounded end is +-inf); a value
    outside raises InputError before anything is built. choices: an enumeration's values."""

    name: str
    kind: str       # "number in [0, 1]", "whole number in [1, inf)", "true or false", "astar|dijkstra|..."
    default: str    # the default as the program prints it
    help: str
    range: Optional[tuple] = None
    choices: List[str] = []


class PlannerInfo(NamedTuple):
    """One planner of the registry: its name, the space it plans in, what it does, its options."""

    name: str
    space: str
    description: str
    options: List[Option]


class FreeComponent(NamedTuple):
    """One connected component of a C-space's free space.

    outer: its boundary, an (N, 2) float64 array, or None when the component is unbounded;
    holes: the C-obstacles inside it, (N, 2) arrays; area: its exact area, a Fraction (None when
    unbounded)."""

    outer: object
    holes: list
    area: Optional[_fractions.Fraction]


class RoundCore(NamedTuple):
    """One C-obstacle of a world with discs or walls: the points within `radius` of a core.

    kind: "point" (points: its centre, a (1, 2) array), "wall" (points: its polyline; radius 0: a
    line crossed never, touched freely) or "polygon" (points: its outer ring; holes its holes);
    radius: an exact Fraction; name: the things it stands for ("discs[0]", "walls[1]", ...)."""

    kind: str
    points: object
    holes: list
    radius: _fractions.Fraction
    name: str


class Graph(NamedTuple):
    """A roadmap or a tree a plan recorded: vertices (V, k) float64, edges (E, 2) int64 indices;
    edge_kinds, for a visibility graph, one word per edge ("supporting" or "separating" bitangent,
    "other" where visibility-full's edge is not tangent at an end), else None."""

    kind: str
    vertices: object
    edges: object
    edge_kinds: Optional[list] = None


class Cells(NamedTuple):
    """A planner's cells: states[row, column] (uint8: 0 not evaluated, 1 free, 2 blocked, 3 ridge),
    cell (0, 0)'s lower-left corner (x0, y0), the cells' size, an optional value per cell
    (values, float32, named value_name) and whether opposite edges meet (an arm's torus)."""

    states: object
    x0: float
    y0: float
    cell_width: float
    cell_height: float
    values: object
    value_name: str
    wraps: bool


def planners() -> List[PlannerInfo]:
    """Every planner of the registry, as `polyplan planners --json -` lists them.

    Each is a PlannerInfo(name, space, description, options); space says what it plans for (a
    translating robot, a rotating robot, a steered car, a planar arm: prm, rrt and their kin are
    listed for each space they plan in) and options are Option(name, kind,
    default, help): polyplan.planner(info.name, problem, **{option.name: value})."""
    return [PlannerInfo(name, space, description, [Option(*o) for o in options])
            for name, space, description, options in _polyplan._planner_list()]


def planner(name: str, problem, **options) -> Planner:
    """The planner `name` built for `problem` (a World or an Arm), with its options as keyword
    arguments: polyplan.planner("visibility", world, search="astar"), polyplan.planner("rrt",
    world, goal_bias=0.2) (an option's name with underscores for its hyphens). In a World whose
    robot is a car, a name registered for the car too (rrt, rrtconnect, ...) plans the car.

    polyplan.planners() lists the names and each one's options. The planner builds its roadmap,
    diagram or grid here, once; each Planner.plan(start=..., goal=...) answers one query with it.
    An option's value may be a number, a string, True or False, or a point (x, y). Raises InputError for an unknown
    planner, one that plans for the other kind of problem, an unknown option or a value the
    option refuses (the message the program prints)."""
    return _polyplan._planner(name, problem, options)


def plan(problem, planner: Optional[str] = None, *, record: bool = True, **options) -> List[Plan]:
    """Every query of `problem` (a World or an Arm) answered by one planner: a list of Plan.

    planner: a name from polyplan.planners(); None: the problem's default, as the program picks it
    ("visibility" for a World, "hybrid-astar" for a car's, "grid" for an Arm). options: the
    planner's options as keyword arguments, spelt with underscores or hyphens, e.g.
    polyplan.plan(w, planner="rrtconnect", seed=3) or polyplan.plan(a, planner="grid",
    resolution=1). record: keep each plan's roadmap, tree, expanded configurations and cells for
    polyplan.plot and polyplan.svg.

    The queries are checked first as the program checks them: a start or goal that is not free
    raises InputError. To plan one query of your own, build the planner once with
    polyplan.planner(...) and call its plan(start=..., goal=...)."""
    return _polyplan._planner(planner, problem, options).plan_all(record)


# What the file readers allow (geometry/input_limits.hpp): nesting and the digits of a number.
_JSON_DEPTH = 32
_INTEGER_BITS = 400  # 100 digits and more are refused as text; str() refuses 4300 digits itself


def _integer(value, where):
    if value.bit_length() > _INTEGER_BITS:
        raise InputError(f"{where}: an integer of more than 100 digits: longer than the supported 100 characters")
    return value


def _json_value(value, where, exact=True, depth=0):
    """A Python value of a world, arm or graph as the file's JSON holds it: numbers exact (a float
    as the Fraction of its double) or, with exact=False, floats as floats. Nesting deeper than a
    file may (a list that holds itself among them) is an InputError, as are non-finite numbers."""
    if depth > _JSON_DEPTH:
        raise InputError(f"{where or 'value'}: nested deeper than the supported {_JSON_DEPTH} levels "
                         "(or a list or dict that holds itself)")
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, _numbers.Integral):  # beyond 64 bits as text, which the readers take exactly
        value = _integer(int(value), where)
        return value if -2**63 <= value < 2**64 else str(value)  # the readers' int64 and uint64
    if isinstance(value, _fractions.Fraction):
        _integer(value.numerator, where), _integer(value.denominator, where)
        if not exact:
            return float(value)
        return f"{value.numerator}/{value.denominator}" if value.denominator != 1 else value.numerator
    if isinstance(value, _decimal.Decimal):
        if not value.is_finite():
            raise InputError(f"{where}: {value} is not a finite number")
        return str(value) if exact else float(value)
    if isinstance(value, _numbers.Real):
        x = float(value)
        if not _math.isfinite(x):
            raise InputError(f"{where}: {x} is not a finite number")
        return _json_value(_fractions.Fraction(x), where) if exact else x
    deeper = depth + 1
    if isinstance(value, dict):
        return {str(k): _json_value(v, f"{where}.{k}" if where else str(k), exact, deeper) for k, v in value.items()}
    if hasattr(value, "tolist") and not isinstance(value, (list, tuple)):  # numpy arrays and scalars
        return _json_value(value.tolist(), where, exact, depth)
    if isinstance(value, (list, tuple)):
        return [_json_value(v, f"{where}[{i}]", exact, deeper) for i, v in enumerate(value)]
    raise InputError(f"{where}: expected a number, a string, a list or a dict, got {type(value).__name__}")


def _from_dict(cls, d, name):
    if not isinstance(d, dict):
        raise InputError(f"{name}: expected a dict, got {type(d).__name__}")
    return cls.from_json(_json.dumps(_json_value(d, "")), name)


def _world_from_dict(d: dict, name: str = "<dict>") -> World:
    """The world a dict describes, in the world file's format (docs/design.md "World file").

    Coordinates may be int, fractions.Fraction, decimal.Decimal, decimal strings ("0.1"), floats
    (the exact value of the double: 0.1 is 3602879701896397/36028797018963968) and numpy values
    or arrays; `name` stands for the file in messages."""
    return _from_dict(World, d, name)


def _arm_from_dict(d: dict, name: str = "<dict>") -> Arm:
    """The arm a dict describes, in the arm file's format (docs/design.md "Arm file"); numbers as in
    World.from_dict."""
    return _from_dict(Arm, d, name)


World.from_dict = staticmethod(_world_from_dict)
Arm.from_dict = staticmethod(_arm_from_dict)
# help() and repr name the classes where users find them: polyplan.World, not polyplan._polyplan.World.
for _cls in (Arm, CSpace, InputError, Plan, Planner, World):
    _cls.__module__ = __name__


def plot(r, ax=None):
    """Draw a Plan (or a list of Plans of one problem, or a World or Arm alone) with matplotlib.

    A world's plans: the obstacles, the C-obstacles, the bounds, the recorded roadmap or tree,
    cells and expanded configurations, and the path from start (o) to goal (*); the rotation
    planner's path also draws the robot along it. A plan that stopped short (not found, with the
    path it walked) is dashed, ends at x and has its status in the legend, where each plan is named
    by its planner and the options it was given ("rrt goal_bias=0.2 seed=3"). An arm's plan: the
    workspace with the arm at configurations along the path (light to dark). Returns the Axes (a
    new figure when ax is None)."""
    from .plotting import plot as _plot
    return _plot(r, ax)


def animate(obj, ax=None, frames=None, interval=50, *, what="path", graph=None, world=None):
    """Watch a plan, a search, a drive or a descent move: a matplotlib FuncAnimation.

    What obj becomes:
      - a Plan of a World: the robot (its polygon, turning for a rotating robot; a car driving its
        arcs; a dot when the world has no robot) moving along the path, over the plan as plot draws it;
      - a Plan of an Arm: the arm moving through its configurations;
      - a Plan with what="search": the configurations its search expanded appearing in order, then
        the path (plan with record=True, which polyplan.plan does);
      - what search_graph returns, with graph= the graph it was given: expansion by expansion, the
        closed vertices, the open list (green) and the vertex expanded, then the path;
      - a Drive (polyplan.replan): the robot driving cell by cell over the map, a cross where it replanned;
      - what potential returns, with world= its world: the potential-field planner descending with
        the same parameters over the field, the critical points marked.
    Anything else raises InputError.

    frames: how many pictures (default: 100 poses along a path; every step of a search or a drive,
    at most 200 of them evenly spaced). interval: milliseconds between pictures. ax: draw there
    (default: a new figure). Keep the animation in a variable until it is shown or saved:
        a = polyplan.animate(plans[0])
        a.save("plan.gif", writer="pillow")     # or "plan.mp4" where ffmpeg is installed
    In Jupyter: from IPython.display import HTML; HTML(a.to_jshtml())."""
    from .animation import animate as _animate
    return _animate(obj, ax, frames, interval, what=what, graph=graph, world=world)


def search_graph(graph, start, goal, method: str = "astar", weight: float = 1.5, frames=None, reopen: bool = False,
                 write_back: bool = False) -> dict:
    """Searches a graph in the course's graph-search homework's format, a file's path or the list of dicts
    itself ({"x": [x, y], "neighbors": [...], "neighbors_cost": [...]}, 0-based; "g" and "backpointer"
    ignored), from vertex `start` to `goal` with `method` and the Euclidean heuristic, as `polyplan
    search` does. Methods: astar, dijkstra (also by the name uniform-cost, the homework's "bfs" that
    orders its queue by g), bfs (fewest edges), dfs, greedy, wastar (weighted A*, f = g + weight * h:
    the textbook's, never re-opening a closed vertex, unless `reopen`) and bidirectional
    (bidirectional Dijkstra: an optimal path, its cost and counts; no trace, labels or frames).
    Returns a dict: found, method (dijkstra for uniform-cost), path (indices), cost (None without a
    path), expanded, generated, expansion_order, trace (one dict per expansion: step, vertex, g, h,
    f, backpointer, open), g and backpointer (lists, one entry per vertex, as the search left them:
    g the cost from the start along the backpointers, inf where never reached; backpointer the index
    of the vertex it was reached from, None for the start and where never reached; both None for
    bidirectional), svg and
    animation (the pictures as SVG text). Raises InputError for a bad graph (naming the vertex),
    vertex or method.

    write_back: also write each vertex's "g" and "backpointer" into the list of dicts given as
    `graph`, as the homework's search does (InputError for a graph given as a file, or with
    bidirectional, whose two searches leave no one backpointer per vertex).

    frames: a folder (created if need be) to draw a plot after every node expansion into,
    step_0001.png, step_0002.png, ...: the graph, the closed vertices, the open list and the vertex
    expanded, its step, g, h and f in the title; the dict then also holds "frames", the PNGs'
    paths. For graphs of at most 2000 vertices and searches of at most 5000 steps (InputError
    beyond). polyplan.animate(result, graph=graph) shows the same as an animation."""
    if not isinstance(write_back, bool):
        raise InputError(f"search_graph: write_back: expected True or False, got {type(write_back).__name__}")
    if write_back and (isinstance(graph, (str, bytes)) or hasattr(graph, "__fspath__")):
        raise InputError("search_graph: write_back: needs the graph as the list of dicts to write into, not a file")
    if write_back and method == "bidirectional":
        raise InputError("search_graph: write_back: bidirectional leaves no one g and backpointer per vertex "
                         "(its two searches label from the start and from the goal)")
    if frames is not None and method == "bidirectional":
        raise InputError("search_graph: frames: bidirectional records no expansions to draw")
    result = _polyplan.search_graph(graph, start, goal, method, weight, reopen)
    if write_back:
        for vertex, g, backpointer in zip(graph, result["g"], result["backpointer"]):
            vertex["g"] = g
            vertex["backpointer"] = backpointer
    if frames is not None:
        from .animation import search_frames
        result["frames"] = search_frames(graph, result, frames, goal)
    return result


# Jupyter shows a World, an Arm (at its first query's start) and a Plan in its problem as the
# program's picture.
World._repr_svg_ = lambda self: svg(self)
Arm._repr_svg_ = lambda self: svg(self)
Plan._repr_svg_ = lambda self: svg(self.problem, self)
