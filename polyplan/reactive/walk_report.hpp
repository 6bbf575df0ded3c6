#pragma once
// How the Bug planners (bug1, bug2, tangent-bug) report a walk: the facts bug.hits and bug.leaves
// (points "(x, y)" in order) and bug.distance; the path, exactly checked, when the robot arrived;
// and, when the query asks for a picture, the marks: the m-line, the hit and leave points, and the
// walk itself where the robot stopped short of the goal.
#include <polyplan/plan/planner.hpp>
#include <polyplan/reactive/boundary_walk.hpp>

#include <optional>
#include <string>
#include <vector>

namespace polyplan::walk {

template <class P>
struct BasicWalk {
  std::vector<P> path;                      // from the start: every point where the robot turned
  std::vector<std::optional<Along>> along;  // along[k]: from path[k] to path[k + 1]
  std::vector<P> hits, leaves;

  explicit BasicWalk(const P& start) : path{start} {}
  // Goes on to p straight, or along the edge (nothing when already there).
  void to(const P& p) { go(p, std::nullopt); }
  void follow(const P& p, Edge edge, bool forward = true) { go(p, Along{edge, forward}); }

 private:
  void go(const P& p, std::optional<Along> how) {
    if (path.back() == p) return;
    path.push_back(p);
    along.push_back(how);
  }
};
using Walk = BasicWalk<Point>;

// Sets the facts and marks; on `arrived`, the path (ending at the goal) and status solved, unless
// the exact check finds the walk invalid (status not_found, naming polyplan's bug). `name` is the
// planner's, for that message. The caller has set any failure before.
void report_walk(PlanReport<ExactPoint>& report, const Boundary& boundary, const Walk& walk, const Query& query,
                 bool arrived, bool record, const std::string& name);

}  // namespace polyplan::walk
