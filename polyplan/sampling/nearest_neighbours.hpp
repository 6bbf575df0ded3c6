#pragma once
// Nearest neighbours of points under a sampling metric (sampling/sampling_space.hpp), for the
// sampling planners: a KD-tree (nanoflann's dynamic index, points added one at a time) whose
// pruning bounds are valid on the torus too, so every answer is the true nearest under the
// planner's own distance, across the 0 = 2π seam (tested against brute force).
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
