#!/usr/bin/env python3
"""Writes grid_medium.json: the course's graph-search homework's medium A* example rebuilt (a grid graph with obstacle cells
removed, as its grid2graph makes one), in the course's graph-search homework's graph_vector format.

8 x 6 vertices one unit apart, 8-connected (a diagonal move only when both cells beside it are
free, as grid2graph's neighbours), costs the Euclidean lengths 1 and sqrt(2), written with the
solved variant's "g" and "backpointer" fields (defaults 0. and None), which readers ignore.
Vertex 0 is the bottom-left corner, the last vertex the top-right one. Run from anywhere:
    python3 data/graphs/make_grid_graph.py
"""
import json
import math
import os

COLUMNS, ROWS = 8, 6
# Obstacle cells (column, row), row 0 at the bottom: a wall with a gap, and a block.
BLOCKED = {(2, 0), (2, 1), (2, 2), (2, 3), (5, 2), (5, 3), (5, 4), (5, 5), (4, 3), (6, 2)}


def main():
    free = [(c, r) for r in range(ROWS) for c in range(COLUMNS) if (c, r) not in BLOCKED]
    index = {cell: i for i, cell in enumerate(free)}
    vertices = []
    for (c, r) in free:
        neighbors, costs = [], []
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                n = (c + dc, r + dr)
                if (dc, dr) == (0, 0) or n not in index:
                    continue
                if dc and dr and ((c + dc, r) not in index or (c, r + dr) not in index):
                    continue  # no corner cutting
                neighbors.append(index[n])
                costs.append(math.sqrt(dc * dc + dr * dr))
        vertices.append({"x": [float(c), float(r)], "neighbors": neighbors, "neighbors_cost": costs,
                         "g": 0.0, "backpointer": None})
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "grid_medium.json")
    with open(path, "w") as out:
        out.write("[\n" + ",\n".join(json.dumps(v) for v in vertices) + "\n]\n")
    print(path, len(vertices), "vertices")


if __name__ == "__main__":
    main()
