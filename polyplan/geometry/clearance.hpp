#pragma once
// How far a configuration or a path stays from what the robot must not enter: the distance from
// the reference point to the free space's boundary (the C-obstacles, and the walls of the bounds).
// A distance is irrational by nature: these are doubles, each the distance computed from the
// exact coordinates' doubles — measures for reports and comparisons, never the reason a path is
// accepted (that is geometry/path_check.hpp's exact test).
#include <polyplan/geometry/cspace.hpp>

#include <vector>

namespace polyplan {

// A point in doubles, for measures.
struct Vec2 {
  double x = 0, y = 0;
};
inline Vec2 approximate(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }
// A double is a rational: the point itself, exactly.
inline ExactPoint exactly(Vec2 p) { return {Rational(p.x), Rational(p.y)}; }

// The distance from p to the segment a-b (a point when a == b).
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b);
// The distance between the segments a-b and c-d, which must not cross (touching is fine).
double distance_between_segments(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// The distance from p to the nearest point of the free space's boundary; 0 on it, and inside a
// C-obstacle the distance to its boundary as well (ask CSpace::locate which side p is on).
double clearance_at(const CSpace& cspace, const ExactPoint& p);

// The smallest clearance along a path (every point of every segment, not only its corners): 0
// for a path that touches a C-obstacle or a wall. For a valid path (one that never crosses the
// boundary) it is the smallest distance between a segment of the path and one of the boundary.
double path_clearance(const CSpace& cspace, const std::vector<ExactPoint>& path);

// The same, with the point of the path where it is attained (the first such place).
struct PathBottleneck {
  double clearance = 0;
  Vec2 at;
};
PathBottleneck path_bottleneck(const CSpace& cspace, const std::vector<ExactPoint>& path);

}  // namespace polyplan
