"""The course's graph-search homework's two-link arm on its torus: the C-space grid of the two joint angles (every cell
decided, blocked ones grey) with the path drawn across it, and the arm moving in the workspace.

    python3 two_link_torus.py [ARM.json] [QUERY] [OUT.png]
"""
import math
import os
import sys

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import ListedColormap

import polyplan

here = os.path.dirname(os.path.abspath(__file__))
arm_file = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "arms", "two_link_points.json")
query = sys.argv[2] if len(sys.argv) > 2 else "hard"
picture = sys.argv[3] if len(sys.argv) > 3 else "two_link_torus.png"

arm = polyplan.read_arm(arm_file)
# Eager evaluation decides every cell first, so that the picture shows the whole torus.
planner = polyplan.planner("grid", arm, resolution=2, evaluation="eager")
r = planner.plan(query=query)
cells = r.cells
blocked = int((cells.states == 2).sum())
print(f"{arm_file}: {arm.joints} links, {len(arm.points)} obstacle points")
print(f"torus grid {cells.states.shape[1]} x {cells.states.shape[0]}: {blocked} blocked cells, "
      f"{cells.states.size - blocked} free")
print(f"query {r.query}: {r.status}" + (f", joints turn {r.length:.3f} rad in {len(r.path)} configurations" if r.found else f" ({r.why_not})"))

fig, (torus, workspace) = plt.subplots(1, 2, figsize=(13, 6))
rows, columns = cells.states.shape
extent = [cells.x0, cells.x0 + columns * cells.cell_width, cells.y0, cells.y0 + rows * cells.cell_height]
torus.imshow(cells.states == 2, origin="lower", extent=extent, cmap=ListedColormap(["white", "#909090"]),
             interpolation="nearest")
if r.found:
    # Angles wrap at 2 pi: the path leaves one edge of the square and comes back at the other.
    angles = np.mod(r.path + cells.cell_width / 2, 2 * math.pi) - cells.cell_width / 2
    jumps = np.flatnonzero(np.abs(np.diff(angles, axis=0)).max(axis=1) > math.pi) + 1
    for piece in np.split(angles, jumps):
        torus.plot(piece[:, 0], piece[:, 1], color="tab:red", lw=2)
    torus.plot(*angles[0], "o", color="tab:red")
    torus.plot(*angles[-1], "*", color="tab:red", ms=12)
torus.set_xlabel("theta 1 (rad)")
torus.set_ylabel("theta 2 (rad)")
torus.set_title(f"C-space torus at 2 degrees: query {r.query}")
polyplan.plot(r, workspace)
workspace.set_title(f"workspace: {r.status}, {len(r.path)} configurations")
fig.savefig(picture, dpi=90, bbox_inches="tight")
print(f"picture: {picture}")
