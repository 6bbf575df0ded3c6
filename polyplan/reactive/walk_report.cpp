#include <polyplan/reactive/walk_report.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

namespace polyplan::walk {
namespace {

std::string texts(const std::vector<Point>& points) {
  std::string out;
  for (const Point& p : points) out += (out.empty() ? "" : " ") + text(p);
  return out;
}

void mark(PlanReport<ExactPoint>& report, const Walk& walk, const Query& query, bool arrived) {
  using Kind = PlanMark<ExactPoint>::Kind;
  report.recording.marks.push_back({Kind::lines, "m-line (start to goal)", {{query.start, query.goal}}});
  if (!arrived) report.recording.marks.push_back({Kind::lines, "the walk, stopped short of the goal", {walk.path}});
  if (!walk.hits.empty()) report.recording.marks.push_back({Kind::points, "hit points", {walk.hits}});
  if (!walk.leaves.empty()) report.recording.marks.push_back({Kind::points, "leave points", {walk.leaves}});
}

}  // namespace

void report_walk(PlanReport<ExactPoint>& report, const CSpace& cspace, const Walk& walk, const Query& query,
                 bool arrived, bool record, const std::string& name) {
  report.facts.set(BugFacts::hits, texts(walk.hits));
  report.facts.set(BugFacts::leaves, texts(walk.leaves));
  report.facts.set(BugFacts::distance, euclidean_length(walk.path));
  if (record) mark(report, walk, query, arrived);
  if (!arrived) return;
  report.succeed();
  report.path = walk.path;
  if (!(report.path.back() == query.goal)) report.path.push_back(query.goal);
  if (report.path.size() == 1) report.path.push_back(query.goal);
  report.length = euclidean_length(report.path);
  report.certificate = {
      true, "exact path check (arrangement zone walk) of the straight runs and the boundary edges followed"};
  // Every point is exact and every run straight or along an edge, so this holds; checked all the
  // same, so that a mistake here is an answer that says so, never a path through an obstacle.
  const PathCheck check = check_path(cspace, report.path);
  if (!check.valid) {
    report.path.clear();
    report.length = 0;
    report.certificate = {};
    report.fail(PlanStatus::not_found, name + "'s walk is not a valid motion (a bug of polyplan's): " + check.reason);
  }
}

}  // namespace polyplan::walk
