#pragma once
// Nearest neighbours of points under a sampling metric (sampling/sampling_space.hpp), for the
// sampling planners: a linear scan while there are few points, then a KD-tree (nanoflann's
// dynamic index, built from all the points once and then added to one at a time) whose pruning
// bounds are valid on the torus too. Either way every answer is the true nearest under the
// planner's own distance, across the 0 = 2π seam (tested against brute force). The switch comes
// at 250 points in 2-D, 500 in 3-D, 2000 in 4-D and 6000 in 6-D: about where the two were
// measured to cross (docs/nearest_neighbours.md).
//
// nanoflann stays in the source file.
#include <polyplan/sampling/sampling_space.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace polyplan {

class NearestNeighbours {
 public:
  // Torus coordinates must lie in [0, 2π) (normalize_angle's range). Throws std::invalid_argument
  // for dimension 0.
  NearestNeighbours(std::size_t dimension, SamplingMetric metric);
  ~NearestNeighbours();
  NearestNeighbours(NearestNeighbours&&) noexcept;
  NearestNeighbours& operator=(NearestNeighbours&&) noexcept;

  std::size_t dimension() const;
  std::size_t size() const;
  std::span<const double> point(std::size_t index) const;

  // Adds a point (dimension() coordinates, copied); returns its index: 0, 1, 2, ... in order.
  std::size_t add(std::span<const double> point);

  // The index of a point nearest to `query` (the lowest index among equally near ones is not
  // promised). Throws std::logic_error when empty.
  std::size_t nearest(std::span<const double> query) const;
  // The min(k, size()) nearest points, nearest first, into `out` (cleared).
  void nearest(std::span<const double> query, std::size_t k, std::vector<std::size_t>& out) const;
  // Every point within `radius` (distance <= radius), nearest first, into `out` (cleared).
  void within(std::span<const double> query, double radius, std::vector<std::size_t>& out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
