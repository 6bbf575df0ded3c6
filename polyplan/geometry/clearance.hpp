#pragma once
// How far a configuration or a path stays from what the robot must not enter: the distance from
// the reference point to the free space's boundary (the C-obstacles, and the walls of the bounds).
// A distance is irrational by nature: these are doubles, each the distance computed from the
// exact coordinates' doubles — measures for reports and comparisons, never the reason a path is
// accepted (that is geometry/path_check.hpp's exact test).
#include <polyplan/geometry/cspace.hpp>

#include <vector>

namespace polyplan {

// The distance from p to the nearest point of the free space's boundary; 0 on it, and inside a
// C-obstacle the distance to its boundary as well (ask CSpace::locate which side p is on).
double clearance_at(const CSpace& cspace, const ExactPoint& p);

// The smallest clearance along a path (every point of every segment, not only its corners): 0
// for a path that touches a C-obstacle or a wall. For a valid path (one that never crosses the
// boundary) it is the smallest distance between a segment of the path and one of the boundary.
double path_clearance(const CSpace& cspace, const std::vector<ExactPoint>& path);

}  // namespace polyplan
