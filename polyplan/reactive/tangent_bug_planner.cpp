#include <polyplan/reactive/tangent_bug_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/visibility_region.hpp>
#include <polyplan/reactive/walk_report.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace polyplan {

using namespace walk;

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::size_t regions_drawn = 6;  // the sensed regions a picture shows: the first stops'

double parse_range(const std::string& text) {
  if (text == "inf" || text == "infinity") return infinity;
  const auto value = detail::parse_real_number(text);
  if (!value || *value < 0)
    throw std::invalid_argument("option sensor-range=" + text + ": expected a number >= 0 or inf");
  return *value;
}

std::string range_text(double range) { return std::isinf(range) ? "inf" : detail::show_number(range); }

// The point of a-b at the rational copy of t, moved on towards the parameter `last` in growing
// steps until `holds` (which must hold at `last`): how an irrational event point becomes a
// rational point on the same line, a few ulps past it.
template <class Holds>
Point first_where(const Point& a, const Point& b, double t, const Rational& last, Holds holds) {
  const double end = to_double(last);
  double step = std::numeric_limits<double>::epsilon() * std::max(std::abs(t), std::numeric_limits<double>::min());
  for (t = std::max(t, 0.0); t < end; t += step, step *= 2)
    if (const Point p = along(a, b, Rational(t)); holds(p)) return p;
  return along(a, b, last);
}

struct Candidate {
  Point to;
  double heuristic;  // d(x, n) + d(n, goal)
};

// The candidate of least heuristic (the first of equals), if any.
std::optional<Candidate> best_of(const std::vector<Candidate>& candidates) {
  std::optional<Candidate> best;
  for (const Candidate& c : candidates)
    if (!best || c.heuristic < best->heuristic) best = c;
  return best;
}

}  // namespace

struct TangentBugPlanner::Impl {
  Boundary boundary;
  VisibilityRegions regions;
  double range;
  TangentBugOptions options;

  Impl(const CSpace& cspace, TangentBugOptions o)
      : boundary(cspace), regions(boundary), range(parse_range(o.sensor_range)), options(std::move(o)) {}

  bool senses(const Point& x, const Point& p) const {
    return std::isinf(range) || squared(x, p) <= Rational(range) * Rational(range);
  }

  // Where the robot at x goes on straight for the goal, given where its straight way is first
  // blocked (`hit`, boundary.first_hit): the goal when the way is free; the point at the range
  // short of the obstacle when that is out of range (the obstacle itself for a touch sensor);
  // nullopt when the blocking obstacle is sensed.
  std::optional<Point> straight_on(const Point& x, const Point& goal, const std::optional<Point>& hit) const {
    if (!hit) return goal;
    if (*hit == x || senses(x, *hit)) return std::nullopt;
    if (range == 0) return *hit;
    const double t = 1 - range / distance(x, *hit);
    return first_where(x, *hit, t, Rational(1), [&](const Point& p) { return senses(p, *hit); });
  }

  // The farthest point the robot at x sees free on its straight way to the goal: d_reach is its
  // distance to the goal.
  Point reach(const Point& x, const Point& goal) const {
    const Point end = boundary.first_hit(x, goal).value_or(goal);
    if (senses(x, end)) return end;
    return along(x, end, Rational(range / distance(x, end)));
  }

  // The discontinuities the robot at x senses and can head for, with d(x, O) + d(O, goal).
  std::vector<Candidate> discontinuities(const Point& x, const Point& goal, const std::vector<Point>& region) const {
    std::vector<Candidate> out;
    for (const auto& [near, far] : windows(boundary, x, region))
      if (senses(x, near) && check_segment(boundary.cspace(), x, near).valid)
        out.push_back({near, distance(x, near) + distance(near, goal)});
    return out;
  }

  // Those of `sensed` nearer the goal than x: the ones motion to the goal may head for.
  static std::vector<Candidate> nearer_goal(const std::vector<Candidate>& sensed, const Point& x, const Point& goal) {
    std::vector<Candidate> out;
    for (const Candidate& c : sensed)
      if (squared(c.to, goal) < squared(x, goal)) out.push_back(c);
    return out;
  }

  // Whether boundary following from x goes forwards along the cycle (the obstacle on the right):
  // yes, unless a discontinuity on the backward side (the end its direction is nearer) is strictly
  // better than every one on the forward side. `ends` = {backward end, forward end}.
  static bool follow_forwards(const Point& x, const std::vector<Candidate>& sensed, const std::vector<Point>& ends) {
    const auto cosine = [&](const Point& end, const Point& o) {
      return to_double(dot(x, end, o)) / distance(x, end) / distance(x, o);
    };
    double best[2] = {infinity, infinity};  // backward, forward
    for (const Candidate& c : sensed) {
      const int side = cosine(ends[1], c.to) >= cosine(ends[0], c.to) ? 1 : 0;
      best[side] = std::min(best[side], c.heuristic);
    }
    return !(best[0] < best[1]);
  }

  // The ends of the boundary edges through x (its neighbours along the cycle when x is a corner).
  std::vector<Point> edge_ends(const Point& x, const Edge& edge) const {
    const std::size_t n = boundary.cycles()[edge.cycle].size();
    const Point& a = boundary.vertex(edge.cycle, edge.index);
    return {a == x ? boundary.vertex(edge.cycle, edge.index + n - 1) : a, boundary.vertex(edge.cycle, edge.index + 1)};
  }

  // Sliding along an edge through x towards the goal: as far as it brings the robot nearer.
  std::optional<Candidate> best_slide(const Point& x, const Point& goal) const {
    std::vector<Candidate> slides;
    if (const auto edge = boundary.edge_at(x))
      for (const Point& end : edge_ends(x, *edge)) {
        if (!(dot(x, end, goal) > 0)) continue;
        const Point to = along(x, end, std::min(Rational(dot(x, goal, end) / squared(x, end)), Rational(1)));
        slides.push_back({to, distance(x, to) + distance(to, goal)});
      }
    return best_of(slides);
  }

  // On the way a-b, the first point nearer the goal than d_followed (squared: `record`); nullopt
  // when there is none.
  static std::optional<Point> nearer_than(const Point& a, const Point& b, const Point& goal, const Rational& record) {
    if (a == b) return std::nullopt;
    const Rational ab = squared(a, b);
    const Rational foot = std::clamp(Rational(dot(a, goal, b) / ab), Rational(0), Rational(1));
    if (!(squared(along(a, b, foot), goal) < record)) return std::nullopt;
    // |a + t(b - a) - goal|² = record: A t² + B t + C = 0 with A = |b - a|², B = 2 (a - goal)·(b - a).
    const double a2 = to_double(ab), b1 = 2 * to_double((a.x - goal.x) * (b.x - a.x) + (a.y - goal.y) * (b.y - a.y));
    const double c0 = to_double(squared(a, goal) - record);
    // The smaller root as c / q (b < 0 here, the distance falling): no cancellation.
    const double q = (-b1 + std::sqrt(std::max(0.0, b1 * b1 - 4 * a2 * c0))) / 2;
    const double root = q > 0 ? c0 / q : 0;
    return first_where(a, b, root, foot, [&](const Point& p) { return squared(p, goal) < record; });
  }
};

TangentBugPlanner::TangentBugPlanner(const CSpace& cspace, TangentBugOptions options)
    : impl_(std::make_unique<Impl>(cspace, std::move(options))) {}

TangentBugPlanner::~TangentBugPlanner() = default;

PlanReport<ExactPoint> TangentBugPlanner::plan(const Query& q, const QueryOptions& query_options) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "tangent-bug");
  facts.set(TangentBugFacts::sensor_range, range_text(r.range));
  Walk walk(q.start);
  Point at = q.start;
  double travelled = 0;
  std::optional<Rational> record;  // d_followed, squared
  std::size_t stops = 0;
  std::vector<std::vector<Point>> sensed;
  const auto finish = [&](bool arrived) {
    if (record) facts.set(TangentBugFacts::d_followed, std::sqrt(to_double(*record)));
    facts.set(TangentBugFacts::stops, stops);
    if (query_options.record && !sensed.empty())
      report.recording.marks.push_back(
          {PlanMark<ExactPoint>::Kind::regions, "sensed (visibility within range) at the first stops", sensed});
    report_walk(report, r.boundary, walk, q, arrived, query_options.record, "tangent-bug");
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  const auto out_of_distance = [&](const std::string& doing) {
    facts.set(QueryFacts::stopped_by, "distance limit");
    const std::string followed = record ? ", d_followed " + detail::show_number(std::sqrt(to_double(*record))) : "";
    report.fail(PlanStatus::limit, "the walk reached max-distance (" + detail::show_number(r.options.max_distance) +
                                       ") at " + text(at) + doing + followed);
    return finish(false);
  };
  // Goes straight to p, or as far as max-distance allows (then false).
  const auto go = [&](const Point& p) {
    const double d = distance(at, p);
    if (travelled + d > r.options.max_distance) {
      at = along(at, p, Rational((r.options.max_distance - travelled) / d));
      walk.to(at);
      return false;
    }
    travelled += d;
    walk.to(p);
    at = p;
    return true;
  };
  if (auto why = r.boundary.query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish(false);
  }
  for (;;) {
    if (++stops > r.options.max_stops) {
      facts.set(QueryFacts::stopped_by, "stop limit");
      report.fail(PlanStatus::limit,
                  "the stop limit (" + std::to_string(r.options.max_stops) + ") ended the walk at " + text(at));
      return finish(false);
    }
    // Motion to the goal.
    const std::optional<Point> hit = r.boundary.first_hit(at, q.goal);
    if (const auto on = r.straight_on(at, q.goal, hit)) {
      if (!go(*on)) return out_of_distance(" heading for the goal");
      if (at == q.goal) return finish(true);
      continue;
    }
    const std::vector<Point> region = r.regions.visible_from(at);
    if (query_options.record && r.range > 0 && sensed.size() < regions_drawn)
      sensed.push_back(within_range(region, at, r.range));
    const std::vector<Candidate> sensed_ends = r.discontinuities(at, q.goal, region);  // sensed once per stop
    std::optional<Candidate> move = best_of(Impl::nearer_goal(sensed_ends, at, q.goal));
    if (const auto slide = r.best_slide(at, q.goal); slide && (!move || slide->heuristic < move->heuristic))
      move = slide;
    if (!move && !(*hit == at)) move = Candidate{*hit, 0};  // no discontinuity to head for: up to the obstacle
    if (move) {
      if (!go(move->to)) return out_of_distance(" heading for the goal");
      continue;
    }
    // A local minimum of the distance to the goal: boundary following.
    const auto edge = r.boundary.edge_at(at);
    if (!edge) {
      report.fail(PlanStatus::not_found,
                  "tangent-bug: blocked at " + text(at) + ", off the boundary (a bug of polyplan's)");
      return finish(false);
    }
    record = squared(at, q.goal);
    walk.hits.push_back(at);
    const std::size_t c = edge->cycle, n = r.boundary.cycles()[c].size();
    const std::vector<Point> ends = r.edge_ends(at, *edge);  // {backwards, forwards}
    const bool forwards = Impl::follow_forwards(at, sensed_ends, ends);
    const bool corner = at == r.boundary.vertex(c, edge->index);
    std::size_t k = forwards ? edge->index + 1 : corner ? edge->index + n - 1 : edge->index;  // the next corner
    // Walk the cycle from corner to corner until d_reach < d_followed.
    for (std::size_t walked = 0;; ++walked, k = forwards ? k + 1 : k + n - 1) {
      if (walked > n) {
        report.fail(
            PlanStatus::no_path,
            "went once round the boundary from " + text(walk.hits.back()) +
                " without coming nearer the goal than d_followed: the goal is unreachable (tangent-bug is complete)");
        return finish(false);
      }
      const Point next = r.boundary.vertex(c, k);
      if (const auto p = Impl::nearer_than(at, next, q.goal, *record)) {  // its own distance falls below d_followed
        if (!go(*p)) return out_of_distance(" following the boundary");
        walk.leaves.push_back(at);
        break;
      }
      if (!go(next)) return out_of_distance(" following the boundary");
      if (const Point seen = r.reach(at, q.goal); squared(seen, q.goal) < *record) {  // it sees a point nearer
        walk.leaves.push_back(at);
        if (!go(seen)) return out_of_distance(" heading for the goal");
        if (at == q.goal) return finish(true);
        break;
      }
    }
  }
}

PlannerEntry<TranslatingRobot> tangent_bug_planner_entry() {
  OptionTable<TangentBugOptions> table;
  table.add(
      "sensor-range", "the range sensor's radius: a number >= 0 (0: touch only), or inf", "number in [0, inf) or inf",
      [](const TangentBugOptions& o) { return o.sensor_range; },
      [](TangentBugOptions& o, std::string_view text) -> std::optional<std::string> {
        const auto value = detail::parse_real_number(text);
        if (text != "inf" && text != "infinity" && !(value && *value >= 0))
          return "expected a number in [0, inf) or inf";
        o.sensor_range = std::string(text);
        return std::nullopt;
      },
      at_least(0));
  table.add("max-distance", &TangentBugOptions::max_distance, "the walk's length before it stops with status limit",
            at_least(0));
  table.add("max-stops", &TangentBugOptions::max_stops,
            "stops (each one sensing) before the walk stops with status limit", at_least(1));
  return make_planner_entry<TranslatingRobot, TangentBugOptions>(
      "tangent-bug",
      "TangentBug: to the goal or the best discontinuity its range sensor sees, following a boundary where that stops "
      "bringing it nearer (Kamon, Rivlin & Rimon)",
      std::move(table),
      [](const CSpace& cspace, const TangentBugOptions& o) { return std::make_unique<TangentBugPlanner>(cspace, o); });
}

}  // namespace polyplan
