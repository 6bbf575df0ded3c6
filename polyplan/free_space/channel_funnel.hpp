#pragma once
// The shortest path through a channel of convex cells (Lee and Preparata's funnel algorithm, in
// the "simple stupid funnel" form navigation meshes use): the cells are glued along portals, the
// segments a path crosses from one cell into the next, and the shortest path from a start in the
// first cell to a goal in the last bends only at portal ends. Exact: every decision is the sign of
// a rational orientation, every bend is a portal end, so the path is rational and never leaves
// the channel's closure.
#include <polyplan/geometry/rational.hpp>

#include <vector>

namespace polyplan {

// A portal's two ends as a traveller crossing it sees them.
struct Portal {
  ExactPoint left, right;
};

// start, the portal ends where the shortest path bends, goal. The channel's cells must be convex,
// start in the closure of the first, goal in the closure of the last, and each portal the shared
// side of two consecutive cells.
std::vector<ExactPoint> funnel_path(const ExactPoint& start, const std::vector<Portal>& portals,
                                    const ExactPoint& goal);

}  // namespace polyplan
