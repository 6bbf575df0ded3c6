#include <polyplan/reactive/walk_report.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/plan/fact_points.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

namespace polyplan::walk {
namespace {

void mark(PlanReport<ExactPoint>& report, const Walk& walk, const Query& query, bool arrived) {
  using Kind = PlanMark<ExactPoint>::Kind;
  report.recording.marks.push_back({Kind::lines, "m-line (start to goal)", {{query.start, query.goal}}});
  if (!arrived) report.recording.marks.push_back({Kind::lines, "the walk, stopped short of the goal", {walk.path}});
  if (!walk.hits.empty()) report.recording.marks.push_back({Kind::points, "hit points", {walk.hits}});
  if (!walk.leaves.empty()) report.recording.marks.push_back({Kind::points, "leave points", {walk.leaves}});
}

}  // namespace

void report_walk(PlanReport<ExactPoint>& report, const Boundary& boundary, const Walk& walk, const Query& query,
                 bool arrived, bool record, const std::string& name) {
  report.facts.set(BugFacts::hits, fact_points(walk.hits));
  report.facts.set(BugFacts::leaves, fact_points(walk.leaves));
  report.facts.set(BugFacts::distance, euclidean_length(walk.path));
  if (record) mark(report, walk, query, arrived);
  std::vector<Point> path = walk.path;
  if (arrived && !(path.back() == query.goal)) path.push_back(query.goal);
  if (path.size() == 1) path.push_back(path.front());
  // Every point is exact and every run straight or along an edge, so this holds; checked all the
  // same, so that a mistake here is an answer that says so, never a path through an obstacle. A
  // walk that stopped short is returned too (where the robot got stuck), after the same check.
  const PathCheck check = boundary.check_path(path);
  if (check.valid) report.path = std::move(path);
  if (!arrived) return;
  if (!check.valid) {
    report.fail(PlanStatus::not_found, name + "'s walk is not a valid motion (a bug of polyplan's): " + check.reason);
    return;
  }
  report.succeed();
  report.length = euclidean_length(report.path);
  report.certificate = {true, "exact path check of the straight runs and the boundary edges followed"};
}

}  // namespace polyplan::walk
