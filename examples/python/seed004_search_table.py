"""The course's C-space and visibility-graph problem set's table: every search of a course on one visibility graph of the the course's C-space and visibility-graph problem set world —
segments in the path, its cost and the nodes explored — printed, and every path in one plot.

    python3 seed004_search_table.py [WORLD.json] [OUT.png]
"""
import os
import sys

import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection

import polyplan

here = os.path.dirname(os.path.abspath(__file__))
world_file = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "worlds", "seed004.json")
picture = sys.argv[2] if len(sys.argv) > 2 else "seed004_search_table.png"

world = polyplan.read_world(world_file)
rows = [("DFS", dict(search="dfs")),
        ("BFS", dict(search="bfs")),
        ("UCS (Dijkstra)", dict(search="dijkstra")),
        ("A* (admissible)", dict(search="astar")),
        ("Weighted A* (w = 3)", dict(search="wastar", weight=3)),
        ("Greedy best-first", dict(search="greedy"))]

# "visibility-full": every visible pair of corners, the graph a course draws.
plans = [polyplan.planner("visibility-full", world, **options).plan() for _, options in rows]
graph = plans[0].graph
print(f"{world_file}: visibility graph with {len(graph.vertices)} vertices and {len(graph.edges)} edges\n")
print(f"{'Algorithm':<22} {'# of segments in path':>22} {'path cost':>12} {'# of nodes explored':>20}")
for (name, _), r in zip(rows, plans):
    if not r.found:
        print(f"{name:<22} {'no path':>22}")
        continue
    print(f"{name:<22} {len(r.path) - 1:>22} {r.length:>12.2f} {r.facts['search']['expanded']:>20}")

fig, ax = plt.subplots(figsize=(8, 8))
polyplan.plot(world, ax)
for (name, _), r, colour in zip(rows, plans, ["grey", "tab:blue", "tab:green", "tab:red", "tab:orange", "tab:purple"]):
    if r.found:
        ax.plot(r.path[:, 0], r.path[:, 1], color=colour, lw=2, label=f"{name}: {len(r.path) - 1} segments, {r.length:.2f}")
ax.add_collection(LineCollection(graph.vertices[graph.edges], colors="#7aa6d6", linewidths=0.3, zorder=0))
ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize="small")  # same paths overlap: UCS under A*, w = 3 under greedy
ax.set_title("the course's C-space and visibility-graph problem set: searches on the visibility graph")
fig.savefig(picture, dpi=100, bbox_inches="tight")
print(f"\npicture: {picture}")
