#pragma once
// Measures of a polyline of exact points.
#include <polyplan/geometry/rational.hpp>

#include <vector>

namespace polyplan {

// The sum of the segments' Euclidean lengths, each the hypot of its exact differences rounded to
// double: irrational by nature, so a double.
double euclidean_length(const std::vector<ExactPoint>& path);

}  // namespace polyplan
