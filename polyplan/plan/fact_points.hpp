#pragma once
// Exact points as a fact's points (plan/plan_report.hpp's FactPoints): the doubles nearest to
// them, for the JSON and for Python, which read facts as numbers.
#include <polyplan/geometry/rational.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <vector>

namespace polyplan {

inline FactPoints fact_points(const std::vector<ExactPoint>& points) {
  FactPoints out;
  out.reserve(points.size());
  for (const ExactPoint& p : points) out.push_back({to_double(p.x), to_double(p.y)});
  return out;
}

}  // namespace polyplan
