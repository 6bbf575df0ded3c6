#pragma once
// Measures of a polyline of exact points.
#include <polyplan/geometry/rational.hpp>

#include <vector>

namespace polyplan {

// The sum of the segments' Euclidean lengths, each the hypot of its exact differences rounded to
// double: irrational by nature, so a double.
double euclidean_length(const std::vector<ExactPoint>& path);

// The same motion without the corners it runs straight through (collinear and strictly between
// their neighbours) and without repeated points: a path that grazes a corner lists it, the one
// that reads better does not (docs/design.md: "if start sees goal, the path is the segment"). Exact.
std::vector<ExactPoint> without_straight_corners(const std::vector<ExactPoint>& path);

// The sign of the turn a -> b -> c: +1 counterclockwise (c left of the line a->b), -1 clockwise,
// 0 collinear. Exact.
int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

}  // namespace polyplan
