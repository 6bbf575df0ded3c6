#include <polyplan/reactive/bug_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/walk_report.hpp>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace polyplan {

using namespace walk;

namespace {

// The planner's core, the same for both spaces: the walks over the boundary.
struct BugWalks {
  Boundary boundary;
  BugKind kind;
  BugOptions options;

  const Point& vertex(std::size_t cycle, std::size_t i) const { return boundary.vertex(cycle, i); }
  std::optional<Point> first_hit(const Point& from, const Point& goal) const { return boundary.first_hit(from, goal); }

  // Bug2's walk round the boundary from the hit point: the first m-line point nearer the goal from
  // which it can head for it; nullopt when the walk comes back to the hit point.
  std::optional<Point> follow_to_leave(const Point& hit, Edge edge, const Query& q, std::vector<Point>& path) const {
    const Rational hit_distance = squared(hit, q.goal);
    const std::size_t n = boundary.cycles()[edge.cycle].size(), hit_edge = edge.index;
    Point at = hit;
    for (std::size_t walked = 0; walked <= n; ++walked, ++edge.index) {
      const bool back = walked > 0 && edge.index % n == hit_edge;  // round again onto the hit point's edge
      const Point& end = back ? hit : vertex(edge.cycle, edge.index + 1);
      std::vector<Rational> ts;
      if (!(at == end)) meetings(at, end, q.start, q.goal, ts);
      std::sort(ts.begin(), ts.end());
      for (const Rational& t : ts) {
        const Point x = along(at, end, t);
        // As near as the hit point only where it is the hit point on a wall's far side; and never
        // heading off to the right of the edge walked (through a wall, whose point has two sides).
        if (squared(x, q.goal) > hit_distance || cross(at, end, q.goal) < 0) continue;
        const auto blocked = first_hit(x, q.goal);
        if (blocked && *blocked == x) continue;
        if (!(x == at)) path.push_back(x);
        return x;
      }
      if (back) return std::nullopt;
      path.push_back(end);
      at = end;
    }
    return std::nullopt;
  }

  // Bug1's walk: once round the boundary from the hit point, then on to the boundary point nearest
  // the goal the shorter way round. Returns that point.
  Point go_round(const Point& hit, Edge edge, const Query& q, std::vector<Point>& path) const {
    const std::size_t n = boundary.cycles()[edge.cycle].size();
    // The loop: hit, the vertices after it, hit again.
    std::vector<Point> loop{hit};
    for (std::size_t k = 1; k <= n; ++k) loop.push_back(vertex(edge.cycle, edge.index + k));
    if (!(loop.back() == hit)) loop.push_back(hit);
    std::vector<double> arc{0};
    for (std::size_t k = 1; k < loop.size(); ++k) arc.push_back(arc.back() + distance(loop[k - 1], loop[k]));
    // The nearest point: on each edge the foot of the perpendicular from the goal, or an end; of
    // equally near ones (both sides of a wall), one on an edge facing the goal.
    Point nearest = hit;
    Rational best = squared(hit, q.goal);
    bool facing = false;
    std::size_t on = 0;
    double at_arc = 0;
    for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
      const Point &a = loop[k], &b = loop[k + 1];
      if (a == b) continue;
      const Rational t = std::clamp(Rational(dot(a, q.goal, b) / squared(a, b)), Rational(0), Rational(1));
      const Point foot = along(a, b, t);
      const bool faces = cross(a, b, q.goal) > 0;
      if (squared(foot, q.goal) < best || (squared(foot, q.goal) == best && faces && !facing))
        best = squared(foot, q.goal), nearest = foot, on = k, at_arc = arc[k] + distance(a, foot), facing = faces;
    }
    path.insert(path.end(), loop.begin() + 1, loop.end());
    const double total = arc.back();
    if (at_arc <= total - at_arc) {
      path.insert(path.end(), loop.begin() + 1, loop.begin() + static_cast<std::ptrdiff_t>(on) + 1);
    } else {
      for (std::size_t k = loop.size() - 2; k > on; --k) path.push_back(loop[k]);
    }
    if (!(path.back() == nearest)) path.push_back(nearest);
    return nearest;
  }

  PlanReport<ExactPoint> plan(const Query& q, const QueryOptions& query_options) const;
};

Boundary boundary_of(const CSpace& cspace, BugKind) { return Boundary(cspace); }
Boundary boundary_of(const RoundWorld& world, BugKind kind) {
  return Boundary(world, kind == BugKind::bug1 ? "bug1" : "bug2");
}

}  // namespace

template <class Space>
struct BasicBugPlanner<Space>::Impl : BugWalks {};

template <class Space>
BasicBugPlanner<Space>::BasicBugPlanner(const typename Space::Problem& problem, BugKind kind, BugOptions options)
    : impl_(std::make_unique<Impl>(Impl{{boundary_of(problem, kind), kind, options}})) {}

template <class Space>
BasicBugPlanner<Space>::~BasicBugPlanner() = default;

template <class Space>
PlanReport<ExactPoint> BasicBugPlanner<Space>::plan(const Query& q, const QueryOptions& query_options) {
  return impl_->plan(q, query_options);
}

PlanReport<ExactPoint> BugWalks::plan(const Query& q, const QueryOptions& query_options) const {
  const BugWalks& r = *this;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  const std::string name = r.kind == BugKind::bug1 ? "bug1" : "bug2";
  facts.set(RoadmapFacts::kind, name);
  Walk walk(q.start);
  std::set<std::size_t> met;
  const auto finish = [&](bool arrived) {
    report_walk(report, r.boundary, walk, q, arrived, query_options.record, name);
    double bound = distance(q.start, q.goal);
    for (const std::size_t c : met)
      bound += r.kind == BugKind::bug1
                   ? 1.5 * r.boundary.perimeter(c)
                   : 0.5 * static_cast<double>(r.boundary.crossings(c, q.start, q.goal)) * r.boundary.perimeter(c);
    facts.set(BugFacts::bound, bound);
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  if (auto why = r.boundary.query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish(false);
  }
  Point at = q.start;
  for (;;) {
    const auto hit = r.first_hit(at, q.goal);
    if (!hit) break;
    if (walk.hits.size() >= r.options.max_hits) {
      facts.set(QueryFacts::stopped_by, "hit limit");
      report.fail(PlanStatus::limit,
                  "the hit limit (" + std::to_string(r.options.max_hits) + ") ended the walk at " + text(at));
      return finish(false);
    }
    walk.to(*hit);
    walk.hits.push_back(*hit);
    const auto edge = r.boundary.edge_at(*hit, {q.goal.x - at.x, q.goal.y - at.y});
    if (!edge) throw std::logic_error("bug planner: a hit point " + text(*hit) + " on no boundary edge");
    met.insert(edge->cycle);
    std::optional<Point> leave;
    if (r.kind == BugKind::bug2) {
      leave = r.follow_to_leave(*hit, *edge, q, walk.path);
    } else {
      const Point nearest = r.go_round(*hit, *edge, q, walk.path);
      const auto blocked = r.first_hit(nearest, q.goal);
      if (!blocked || !(*blocked == nearest)) leave = nearest;
    }
    if (!leave) {
      report.fail(PlanStatus::no_path,
                  std::string(r.kind == BugKind::bug1 ? "round the obstacle hit at " + text(*hit) +
                                                            ", the point nearest the goal cannot head for it"
                                                      : "the walk round the obstacle came back to its hit point " +
                                                            text(*hit) + " without a leave point") +
                      ": the goal is unreachable (" + name + " is complete)");
      return finish(false);
    }
    walk.leaves.push_back(*leave);
    at = *leave;
  }
  walk.to(q.goal);
  return finish(true);
}

template <class Space>
PlannerEntry<Space> bug_planner_entry(BugKind kind) {
  OptionTable<BugOptions> table;
  table.add("max-hits", &BugOptions::max_hits, "obstacles hit before the walk stops with status limit", at_least(1));
  const bool one = kind == BugKind::bug1;
  return make_planner_entry<Space, BugOptions>(
      one ? "bug1" : "bug2",
      one ? "Bug1: to the goal, round each obstacle hit, leaving from its point nearest the goal (Lumelsky & Stepanov)"
          : "Bug2: along the start-goal line, round each obstacle hit until the line is met nearer the goal (Lumelsky "
            "& Stepanov)",
      std::move(table), [kind](const typename Space::Problem& problem, const BugOptions& o) {
        return std::make_unique<BasicBugPlanner<Space>>(problem, kind, o);
      });
}

template class BasicBugPlanner<TranslatingRobot>;
template class BasicBugPlanner<RoundRobot>;
template PlannerEntry<TranslatingRobot> bug_planner_entry<TranslatingRobot>(BugKind);
template PlannerEntry<RoundRobot> bug_planner_entry<RoundRobot>(BugKind);

}  // namespace polyplan
