#pragma once
// The distance a linear scan of nearest neighbours compares (sampling/nearest_neighbours.cpp, and
// the scan it was raced against in bench/nearest_neighbours_race.cpp): summed coordinate by
// coordinate in the order the KD-tree's metrics sum it, so that scan and tree give the same double.
// On the torus sampling_distance's sum; in the plane the square of its Euclidean distance
// (nanoflann's metric_L2_Simple).
#include <polyplan/geometry/angles.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace polyplan::detail {

// A nonzero fixed_dimension unrolls the loop for the planners' dimensions.
template <SamplingMetric metric, std::size_t fixed_dimension = 0>
double scan_distance(const double* a, const double* b, std::size_t dimension) {
  const std::size_t n = fixed_dimension != 0 ? fixed_dimension : dimension;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = std::fabs(b[i] - a[i]);
    sum += metric == SamplingMetric::torus ? std::min(e, two_pi - e) : e * e;
  }
  return sum;
}

// Returns f(the scan distance for this metric), unrolled for dimensions 2, 3, 4 and 6 (the
// planners' polygon worlds and arms): the choice is made once a query rather than once a coordinate.
template <class F>
decltype(auto) with_scan_distance(SamplingMetric metric, std::size_t dimension, F&& f) {
  const auto for_metric = [&]<SamplingMetric m>() -> decltype(auto) {
    switch (dimension) {
      case 2: return f(scan_distance<m, 2>);
      case 3: return f(scan_distance<m, 3>);
      case 4: return f(scan_distance<m, 4>);
      case 6: return f(scan_distance<m, 6>);
      default: return f(scan_distance<m>);
    }
  };
  if (metric == SamplingMetric::torus) return for_metric.template operator()<SamplingMetric::torus>();
  return for_metric.template operator()<SamplingMetric::euclidean>();
}

}  // namespace polyplan::detail
