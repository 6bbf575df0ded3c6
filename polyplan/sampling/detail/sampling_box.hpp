#pragma once
// The box a world's sampling space draws from (sampling/polygon_sampling_space.cpp,
// round_sampling_space.cpp), in doubles: a picture of where to sample, never a decision.
#include <polyplan/geometry/rational.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>

namespace polyplan::detail {

struct SamplingBox {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;

  void add(double x, double y) {
    xmin = std::min(xmin, x), ymin = std::min(ymin, y), xmax = std::max(xmax, x), ymax = std::max(ymax, y);
  }
  void add(const ExactPoint& p) { add(to_double(p.x), to_double(p.y)); }
  bool empty() const { return !(xmin <= xmax && ymin <= ymax); }
  std::optional<std::string> outside(std::span<const double> c) const {
    return outside_box(c[0], c[1], xmin, ymin, xmax, ymax);
  }

  // A world without bounds: what the box holds (the origin when nothing) grown by a tenth of its
  // diagonal, and one, on every side — room to go round everything.
  void grow_for_unbounded() {
    if (empty()) add(0, 0);
    const double margin = std::hypot(xmax - xmin, ymax - ymin) / 10 + 1;
    xmin -= margin, ymin -= margin, xmax += margin, ymax += margin;
  }
};

}  // namespace polyplan::detail
