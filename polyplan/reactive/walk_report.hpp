#pragma once
// How the Bug planners (bug1, bug2, tangent-bug) report a walk: the facts bug.hits and bug.leaves
// (points "(x, y)" in order) and bug.distance; the path, exactly checked, when the robot arrived;
// and, when the query asks for a picture, the marks: the m-line, the hit and leave points, and the
// walk itself where the robot stopped short of the goal.
#include <polyplan/plan/planner.hpp>
#include <polyplan/reactive/boundary_walk.hpp>

#include <string>
#include <vector>

namespace polyplan::walk {

struct Walk {
  std::vector<Point> path;  // from the start: every point where the robot turned
  std::vector<Point> hits, leaves;

  explicit Walk(const Point& start) : path{start} {}
  // Goes on to p (nothing when already there).
  void to(const Point& p) {
    if (!(path.back() == p)) path.push_back(p);
  }
};

// Sets the facts and marks; on `arrived`, the path (ending at the goal) and status solved, unless
// the exact check finds the walk invalid (status not_found, naming polyplan's bug). `name` is the
// planner's, for that message. The caller has set any failure before.
void report_walk(PlanReport<ExactPoint>& report, const Boundary& boundary, const Walk& walk, const Query& query,
                 bool arrived, bool record, const std::string& name);

}  // namespace polyplan::walk
