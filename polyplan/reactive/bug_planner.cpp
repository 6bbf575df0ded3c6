#include <polyplan/reactive/bug_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/detail/arc_boundary.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/walk_report.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {

using namespace walk;

namespace {

// The planner's core, the same for both spaces: the walks over the boundary B — walk::Boundary
// (straight edges, rational points) for a polygon world, walk::ArcBoundary (segments and arcs, real
// algebraic points) for a round one.
template <class B>
struct BugWalks {
  using P = typename B::Point;
  B boundary;
  BugKind kind;
  BugOptions options;

  // Bug2's walk round the boundary from the hit point: the first m-line point nearer the goal from
  // which it can head for it; nullopt when the walk comes back to the hit point.
  std::optional<P> follow_to_leave(const P& hit, Edge edge, const P& start, const P& goal, BasicWalk<P>& walk) const {
    const auto hit_distance = B::squared_distance(hit, goal);
    const std::size_t n = boundary.size(edge.cycle), hit_edge = edge.index % n;
    P at = hit;
    for (std::size_t walked = 0; walked <= n; ++walked, edge.index = (edge.index + 1) % n) {
      const bool back = walked > 0 && edge.index == hit_edge;  // round again onto the hit point's edge
      const P end = back ? hit : boundary.end(edge);
      for (const P& x : boundary.line_points(edge, at, end, start, goal)) {
        // As near as the hit point only where it is the hit point on a wall's far side; and never
        // heading off to the right of the edge walked (through a wall, whose point has two sides).
        if (B::squared_distance(x, goal) > hit_distance || boundary.side(edge, x, goal) < 0) continue;
        const auto blocked = boundary.first_hit(x, goal);
        if (blocked && *blocked == x) continue;
        walk.follow(x, edge);
        return x;
      }
      walk.follow(end, edge);
      if (back) return std::nullopt;  // round again at the hit point
      at = end;
    }
    return std::nullopt;
  }

  // A part of an edge walked, from one of its points to a later one.
  struct Part {
    Edge edge;
    P from, to;
  };

  // Bug1's walk: once round the boundary from the hit point, then on to the boundary point nearest
  // the goal the shorter way round. Returns that point and the edge it lies on.
  std::pair<P, Edge> go_round(const P& hit, Edge edge, const P& goal, BasicWalk<P>& walk) const {
    const std::size_t n = boundary.size(edge.cycle);
    // The loop: from hit to its edge's end, the edges after it, from the hit edge's start to hit.
    std::vector<Part> loop;
    P at = hit;
    for (std::size_t k = 0; k < n; ++k) {
      const Edge e{edge.cycle, (edge.index + k) % n};
      loop.push_back({e, at, boundary.end(e)});
      at = boundary.end(e);
    }
    loop.push_back({Edge{edge.cycle, edge.index % n}, at, hit});
    // The nearest point: of equally near ones (both sides of a wall), one on an edge facing the goal.
    std::vector<double> arc{0};
    for (const Part& part : loop) arc.push_back(arc.back() + boundary.length(part.edge, part.from, part.to));
    P nearest = hit;
    auto best = B::squared_distance(hit, goal);
    bool facing = false;
    std::size_t on = 0;
    double at_arc = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Part& part = loop[k];
      if (part.from == part.to) continue;
      const P foot = boundary.nearest(part.edge, part.from, part.to, goal);
      const auto d = B::squared_distance(foot, goal);
      const bool faces = boundary.side(part.edge, foot, goal) > 0;
      if (d < best || (d == best && faces && !facing))
        best = d, nearest = foot, on = k, at_arc = arc[k] + boundary.length(part.edge, part.from, foot), facing = faces;
    }
    for (const Part& part : loop) walk.follow(part.to, part.edge);
    if (at_arc <= arc.back() - at_arc) {
      for (std::size_t k = 0; k < on; ++k) walk.follow(loop[k].to, loop[k].edge);
      walk.follow(nearest, loop[on].edge);
    } else {
      for (std::size_t k = loop.size() - 1; k > on; --k) walk.follow(loop[k].from, loop[k].edge, false);
      walk.follow(nearest, loop[on].edge, false);
    }
    return {nearest, loop[on].edge};
  }

  PlanReport<ExactPoint> plan(const Query& q, const QueryOptions& query_options) const;
};

template <class B>
PlanReport<ExactPoint> BugWalks<B>::plan(const Query& q, const QueryOptions& query_options) const {
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  const std::string name = kind == BugKind::bug1 ? "bug1" : "bug2";
  facts.set(RoadmapFacts::kind, name);
  const P start = B::point(q.start), goal = B::point(q.goal);
  BasicWalk<P> walk(start);
  std::set<std::size_t> met;
  const auto finish = [&](bool arrived) {
    report_walk(report, boundary, walk, q, arrived, query_options.record, name);
    double bound = std::sqrt(to_double(walk::squared(q.start, q.goal)));
    for (const std::size_t c : met)
      bound += kind == BugKind::bug1
                   ? 1.5 * boundary.perimeter(c)
                   : 0.5 * static_cast<double>(boundary.crossings(c, start, goal)) * boundary.perimeter(c);
    facts.set(BugFacts::bound, bound);
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  if (auto why = boundary.query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish(false);
  }
  P at = start;
  for (;;) {
    const auto hit = boundary.first_hit(at, goal);
    if (!hit) break;
    if (walk.hits.size() >= options.max_hits) {
      facts.set(QueryFacts::stopped_by, "hit limit");
      report.fail(PlanStatus::limit,
                  "the hit limit (" + std::to_string(options.max_hits) + ") ended the walk at " + text(at));
      return finish(false);
    }
    walk.to(*hit);
    walk.hits.push_back(*hit);
    const auto edge = boundary.edge_at(*hit, P{goal.x - at.x, goal.y - at.y});
    if (!edge) throw std::logic_error("bug planner: a hit point " + text(*hit) + " on no boundary edge");
    met.insert(edge->cycle);
    std::optional<P> leave;
    if (kind == BugKind::bug2) {
      leave = follow_to_leave(*hit, *edge, start, goal, walk);
    } else {
      const auto [nearest, on] = go_round(*hit, *edge, goal, walk);
      // It leaves where it can head for the goal: not into the obstacle, and not off the right of
      // the edge it is on (through a wall, whose points have two sides).
      const auto blocked = boundary.first_hit(nearest, goal);
      if ((!blocked || !(*blocked == nearest)) && boundary.side(on, nearest, goal) >= 0) leave = nearest;
    }
    if (!leave) {
      report.fail(PlanStatus::no_path,
                  std::string(kind == BugKind::bug1 ? "round the obstacle hit at " + text(*hit) +
                                                          ", the point nearest the goal cannot head for it"
                                                    : "the walk round the obstacle came back to its hit point " +
                                                          text(*hit) + " without a leave point") +
                      ": the goal is unreachable (" + name + " is complete)");
      return finish(false);
    }
    walk.leaves.push_back(*leave);
    at = *leave;
  }
  walk.to(goal);
  return finish(true);
}

// The boundary each space's planner walks.
template <class Space>
struct BoundaryOf {
  using type = Boundary;  // a polygon world's C-space
};
template <>
struct BoundaryOf<RoundRobot> {
  using type = ArcBoundary;
};

}  // namespace

template <class Space>
struct BasicBugPlanner<Space>::Impl : BugWalks<typename BoundaryOf<Space>::type> {};

template <class Space>
BasicBugPlanner<Space>::BasicBugPlanner(const typename Space::Problem& problem, BugKind kind, BugOptions options)
    : impl_(std::make_unique<Impl>(Impl{{typename BoundaryOf<Space>::type(problem), kind, options}})) {}

template <class Space>
BasicBugPlanner<Space>::~BasicBugPlanner() = default;

template <class Space>
PlanReport<ExactPoint> BasicBugPlanner<Space>::plan(const Query& q, const QueryOptions& query_options) {
  return impl_->plan(q, query_options);
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
