#include <polyplan/reactive/tangent_bug_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/detail/tangent_senses.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/walk_report.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
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

double measure(const Rational& q) { return to_double(q); }
double measure(const Algebraic& x) { return approximate(x); }
// A measure for choosing among moves only (the heuristic d(x, O) + d(O, goal), the directions):
// CORE's own double (53 bits, a unit in the last place off at worst), where approximate() refines
// a deep number to 80 bits to round it to nearest.
double estimate(const Rational& q) { return to_double(q); }
double estimate(const Algebraic& x) { return x.doubleValue(); }

// The direction of travel along edge e at its point x, exactly.
Point heading(const Boundary& boundary, Edge e, const Point&) {
  return {boundary.end(e).x - boundary.start(e).x, boundary.end(e).y - boundary.start(e).y};
}
AP heading(const ArcBoundary& boundary, Edge e, const AP& x) { return boundary.heading(boundary.piece(e), x); }

// The walk over the boundary that S senses (PolygonSenses or ArcSenses, detail/tangent_senses.hpp).
template <class S>
struct TangentWalk {
  using B = typename S::Boundary;
  using P = typename B::Point;
  using N = typename S::Number;

  B boundary;
  S senses;
  TangentBugOptions options;

  template <class Problem>
  TangentWalk(const Problem& problem, TangentBugOptions o)
      : boundary(problem), senses(boundary, parse_range(o.sensor_range)), options(std::move(o)) {}

  // A move: to a point, straight or along an edge, with d(x, to) + d(to, goal); `from_x`: the
  // point computed from where the robot sets out (a touching point, where its way hits).
  struct Candidate {
    P to;
    double heuristic;
    std::optional<Along> along;
    bool from_x = false;
  };

  static double distance(const P& a, const P& b) { return std::sqrt(measure(B::squared_distance(a, b))); }
  static double about(const P& a, const P& b) { return std::sqrt(estimate(B::squared_distance(a, b))); }
  static N dot(const P& u, const P& v) { return u.x * v.x + u.y * v.y; }

  // The candidate of least heuristic (the first of equals), if any.
  static std::optional<Candidate> best_of(const std::vector<Candidate>& candidates) {
    std::optional<Candidate> best;
    for (const Candidate& c : candidates)
      if (!best || c.heuristic < best->heuristic) best = c;
    return best;
  }

  static N cross(const P& u, const P& v) { return u.x * v.y - u.y * v.x; }

  // Whether direction d lies in the closed wedge turning counter-clockwise from a to b (all round
  // when b is a's direction).
  static bool in_wedge(const P& a, const P& b, const P& d) {
    const auto half = [&](const P& v) {
      return cross(a, v) > N(0) || (cross(a, v) == N(0) && dot(a, v) > N(0)) ? 0 : 1;
    };
    if (cross(a, b) == N(0) && dot(a, b) > N(0)) return true;
    const int hb = half(b), hd = half(d);
    return hd < hb || (hd == hb && !(cross(b, d) > N(0)));
  }

  // Whether the robot at x, on edge `on` if any, may set out along d: into the free side of the
  // boundary it is on (a wall's point has two sides, and the walk is on one). Off the boundary,
  // and into the obstacles, the exact test of the way (boundary.first_hit) decides.
  bool may_set_out(const P& x, const std::optional<Edge>& on, const P& d) const {
    if (!on) return true;
    const P ahead = heading(boundary, *on, x);
    if (!(x == boundary.start(*on))) return !(cross(ahead, d) < N(0));
    const P before = heading(boundary, previous(*on), x);
    return in_wedge(ahead, P{-before.x, -before.y}, d);
  }

  // Where the straight way from x (on edge `on`, if any) to p first stops being free.
  std::optional<P> first_hit(const P& x, const std::optional<Edge>& on, const P& p) const {
    if (!may_set_out(x, on, P{p.x - x.x, p.y - x.y})) return x;
    return boundary.first_hit(x, p);
  }

  // The edge before e along its cycle.
  Edge previous(Edge e) const { return {e.cycle, (e.index + boundary.size(e.cycle) - 1) % boundary.size(e.cycle)}; }

  // Where the robot at x goes on straight for the goal, given where its straight way is first
  // blocked (`hit`, boundary.first_hit): the goal when the way is free; the point at the range
  // short of the obstacle when that is out of range (the obstacle itself for a touch sensor);
  // nullopt when the blocking obstacle is sensed.
  std::optional<P> straight_on(const P& x, const P& goal, const std::optional<P>& hit) const {
    if (!hit) return goal;
    if (*hit == x || senses.senses(x, *hit)) return std::nullopt;
    if (senses.range() == 0) return *hit;
    return senses.short_of(x, *hit, goal);
  }

  // The farthest point the robot at x sees free on its straight way to the goal: d_reach is its
  // distance to the goal.
  P reach(const P& x, const std::optional<Edge>& on, const P& goal) const {
    const P end = first_hit(x, on, goal).value_or(goal);
    return senses.senses(x, end) ? end : senses.ahead(x, end, goal);
  }

  // The points that may be discontinuities at x, with d(x, O) + d(O, goal), least first (equals in
  // the order the senses give them). Points computed from x only where x is not itself computed
  // from an earlier stop (`derived`): a touching point from a touching point is a number of degree
  // four over the world's, and each stop more squares it; CORE decides touching at such points
  // only very slowly. From a derived point the robot heads for corners, slides and hit points,
  // and looks for touching lines again where a slide ends.
  std::vector<Candidate> candidates(const P& x, bool derived, const P& goal) const {
    std::vector<Candidate> out;
    for (const auto& [o, from_x] : senses.candidates(x, !derived))
      out.push_back({o, about(x, o) + about(o, goal), std::nullopt, from_x});
    std::stable_sort(out.begin(), out.end(),
                     [](const Candidate& a, const Candidate& b) { return a.heuristic < b.heuristic; });
    return out;
  }

  // The best discontinuity nearer the goal than x: the one motion to the goal may head for.
  std::optional<Candidate> best_nearer_goal(const std::vector<Candidate>& candidates, const P& x,
                                            const std::optional<Edge>& on, const P& goal) const {
    for (const Candidate& c : candidates)
      if (B::squared_distance(c.to, goal) < B::squared_distance(x, goal) && senses_from(x, on, c.to)) return c;
    return std::nullopt;
  }

  // All the discontinuities the robot at x senses (boundary following chooses its way by them).
  std::vector<Candidate> discontinuities(const std::vector<Candidate>& candidates, const P& x,
                                         const std::optional<Edge>& on) const {
    std::vector<Candidate> out;
    for (const Candidate& c : candidates)
      if (senses_from(x, on, c.to)) out.push_back(c);
    return out;
  }

  // Whether o is a discontinuity the robot at x on edge `on` senses, on its side of the boundary.
  bool senses_from(const P& x, const std::optional<Edge>& on, const P& o) const {
    return may_set_out(x, on, P{o.x - x.x, o.y - x.y}) && senses.discontinuity(x, o);
  }

  // The two ways along the boundary from x on edge e: forwards along e, and back along e (or along
  // the edge before, when x is e's start). Each as {edge, forward, the end it walks to}.
  std::vector<std::pair<Along, P>> ways(const P& x, Edge e) const {
    std::vector<std::pair<Along, P>> out;
    if (!(x == boundary.end(e))) out.push_back({Along{e, true}, boundary.end(e)});
    const Edge back = x == boundary.start(e) ? previous(e) : e;
    out.push_back({Along{back, false}, boundary.start(back)});
    return out;
  }

  // The direction a way sets out in from x.
  P setting_out(const Along& way, const P& x) const {
    const P h = heading(boundary, way.edge, x);
    return way.forward ? h : P{-h.x, -h.y};
  }

  // Whether boundary following from x goes forwards along the cycle (the obstacle on the right):
  // yes, unless a discontinuity on the backward side (the way out it is nearer in direction) is
  // strictly better than every one on the forward side.
  bool follow_forwards(const P& x, Edge e, const std::vector<Candidate>& sensed) const {
    const P forward = heading(boundary, e, x), backward = setting_out(ways(x, e).back().first, x);
    const auto cosine = [&](const P& way, const P& o) {
      const P to{o.x - x.x, o.y - x.y};
      return estimate(dot(way, to)) / std::sqrt(estimate(dot(way, way))) / about(x, o);
    };
    double best[2] = {infinity, infinity};  // backward, forward
    for (const Candidate& c : sensed) {
      const int side = cosine(forward, c.to) >= cosine(backward, c.to) ? 1 : 0;
      best[side] = std::min(best[side], c.heuristic);
    }
    return !(best[0] < best[1]);
  }

  // Sliding along the edge through x towards the goal: as far as it brings the robot nearer all
  // the way (setting out not away from the goal, towards the part's nearest point).
  std::optional<Candidate> best_slide(const P& x, const std::optional<Edge>& edge, const P& goal) const {
    std::vector<Candidate> slides;
    if (!edge) return std::nullopt;
    for (const auto& [way, end] : ways(x, *edge)) {
      const P to_goal{goal.x - x.x, goal.y - x.y};
      if (dot(setting_out(way, x), to_goal) < N(0)) continue;
      const P nearest =
          way.forward ? boundary.nearest(way.edge, x, end, goal) : boundary.nearest(way.edge, end, x, goal);
      if (!(B::squared_distance(nearest, goal) < B::squared_distance(x, goal))) continue;
      const P to = senses.slide_end(way.edge, way.forward, x, nearest, goal);
      slides.push_back({to, walked(x, to, way) + about(to, goal), way});
    }
    return best_of(slides);
  }

  // The length from a to b, straight or along an edge.
  double walked(const P& a, const P& b, const std::optional<Along>& along) const {
    if (!along) return distance(a, b);
    return along->forward ? boundary.length(along->edge, a, b) : boundary.length(along->edge, b, a);
  }

  PlanReport<ExactPoint> plan(const Query& q, const QueryOptions& query_options) const;
};

template <class S>
PlanReport<ExactPoint> TangentWalk<S>::plan(const Query& q, const QueryOptions& query_options) const {
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "tangent-bug");
  facts.set(TangentBugFacts::sensor_range, range_text(senses.range()));
  const P goal = B::point(q.goal);
  BasicWalk<P> walk(B::point(q.start));
  P at = walk.path.front();
  typename S::Travel travel{};  // the walk's length, to decide max-distance (exactly on polygons)
  std::optional<N> record;      // d_followed, squared
  std::size_t stops = 0;
  std::vector<std::vector<ExactPoint>> sensed;
  const auto followed = [&] { return std::sqrt(measure(*record)); };
  const auto finish = [&](bool arrived) {
    if (record) facts.set(TangentBugFacts::d_followed, followed());
    facts.set(TangentBugFacts::stops, stops);
    if (query_options.record && !sensed.empty())
      report.recording.marks.push_back(
          {PlanMark<ExactPoint>::Kind::regions, "sensed (visibility within range) at the first stops", sensed});
    report_walk(report, boundary, walk, q, arrived, query_options.record, "tangent-bug");
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  const auto out_of_distance = [&](const std::string& doing) {
    facts.set(QueryFacts::stopped_by, "distance limit");
    const std::string why_followed = record ? ", d_followed " + detail::show_number(followed()) : "";
    report.fail(PlanStatus::limit, "the walk reached max-distance (" + detail::show_exact(options.max_distance) +
                                       ") at " + text(at) + doing + why_followed);
    return finish(false);
  };
  // How the robot came to where it is: along an edge, or straight in a direction.
  std::optional<Along> came_along;
  P came_in{N(0), N(0)};
  // The boundary edge the robot is on, if any: the one it came along, else the one its way ran into
  // (at a wall, the side it is on).
  const auto edge_here = [&]() -> std::optional<Edge> {
    if (!came_along) return boundary.edge_at(at, came_in);
    const Edge e = came_along->edge;
    if (came_along->forward && at == boundary.end(e)) return Edge{e.cycle, (e.index + 1) % boundary.size(e.cycle)};
    return e;
  };
  bool derived = false;  // where the robot is was computed from an earlier stop's position
  // Goes to p, straight or along an edge, or as far as max-distance allows (then false). `computed`:
  // p was computed from where the robot is.
  const auto go = [&](const P& p, const std::optional<Along>& along, bool computed) {
    came_along = along;
    derived = computed;
    if (!along) came_in = P{p.x - at.x, p.y - at.y};
    const double d = walked(at, p, along);
    if (S::beyond(travel, at, p, d, options.max_distance)) {
      at = senses.cut(at, p, std::clamp((to_double(options.max_distance) - S::walked_so_far(travel)) / d, 0.0, 1.0),
                      along);
      if (along) walk.follow(at, along->edge, along->forward);
      else walk.to(at);
      return false;
    }
    S::extend(travel, at, p, d);
    if (along) walk.follow(p, along->edge, along->forward);
    else walk.to(p);
    at = p;
    return true;
  };
  if (auto why = boundary.query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish(false);
  }
  for (;;) {
    if (++stops > options.max_stops) {
      facts.set(QueryFacts::stopped_by, "stop limit");
      report.fail(PlanStatus::limit,
                  "the stop limit (" + std::to_string(options.max_stops) + ") ended the walk at " + text(at));
      return finish(false);
    }
    // Motion to the goal.
    const std::optional<Edge> here = edge_here();
    const std::optional<P> hit = first_hit(at, here, goal);
    if (const auto on = straight_on(at, goal, hit)) {
      if (!go(*on, std::nullopt, !(*on == goal))) return out_of_distance(" heading for the goal");
      if (at == goal) return finish(true);
      continue;
    }
    if (query_options.record && senses.range() > 0 && sensed.size() < regions_drawn) {
      if (auto region = senses.region(at); !region.empty()) sensed.push_back(std::move(region));
    }
    const std::vector<Candidate> sensed_ends = candidates(at, derived, goal);  // sensed once per stop
    std::optional<Candidate> move = best_nearer_goal(sensed_ends, at, here, goal);
    if (const auto slide = best_slide(at, here, goal); slide && (!move || slide->heuristic < move->heuristic))
      move = slide;
    if (!move && !(*hit == at)) move = Candidate{*hit, 0, std::nullopt, true};  // no discontinuity: up to the obstacle
    if (move) {
      if (!go(move->to, move->along, move->from_x)) return out_of_distance(" heading for the goal");
      continue;
    }
    // A local minimum of the distance to the goal: boundary following.
    if (!here) {
      report.fail(PlanStatus::not_found,
                  "tangent-bug: blocked at " + text(at) + ", off the boundary (a bug of polyplan's)");
      return finish(false);
    }
    record = B::squared_distance(at, goal);
    walk.hits.push_back(at);
    const std::size_t n = boundary.size(here->cycle);
    const auto both_ways = ways(at, *here);  // {forwards, back}
    Along way = follow_forwards(at, *here, discontinuities(sensed_ends, at, here)) ? both_ways.front().first
                                                                                   : both_ways.back().first;
    // Walk the cycle from corner to corner until d_reach < d_followed.
    for (std::size_t walked = 0;; ++walked) {
      if (walked > n) {
        report.fail(
            PlanStatus::no_path,
            "went once round the boundary from " + text(walk.hits.back()) +
                " without coming nearer the goal than d_followed: the goal is unreachable (tangent-bug is complete)");
        return finish(false);
      }
      const P next = way.forward ? boundary.end(way.edge) : boundary.start(way.edge);
      if (const auto p = senses.nearer_than(way.edge, way.forward, at, next, goal, *record)) {  // below d_followed
        if (!go(*p, way, true)) return out_of_distance(" following the boundary");
        walk.leaves.push_back(at);
        break;
      }
      if (!go(next, way, false)) return out_of_distance(" following the boundary");
      if (const P seen = reach(at, edge_here(), goal);
          B::squared_distance(seen, goal) < *record) {  // it sees a point nearer
        walk.leaves.push_back(at);
        if (!go(seen, std::nullopt, !(seen == goal))) return out_of_distance(" heading for the goal");
        if (at == goal) return finish(true);
        break;
      }
      way.edge = way.forward ? Edge{way.edge.cycle, (way.edge.index + 1) % n} : previous(way.edge);
    }
  }
}

// The senses of each space's planner.
template <class Space>
struct SensesOf {
  using type = PolygonSenses;  // a polygon world's C-space
};
template <>
struct SensesOf<RoundRobot> {
  using type = ArcSenses;
};

}  // namespace

template <class Space>
struct BasicTangentBugPlanner<Space>::Impl : TangentWalk<typename SensesOf<Space>::type> {
  using TangentWalk<typename SensesOf<Space>::type>::TangentWalk;
};

template <class Space>
BasicTangentBugPlanner<Space>::BasicTangentBugPlanner(const typename Space::Problem& problem, TangentBugOptions options)
    : impl_(std::make_unique<Impl>(problem, std::move(options))) {}

template <class Space>
BasicTangentBugPlanner<Space>::~BasicTangentBugPlanner() = default;

template <class Space>
PlanReport<ExactPoint> BasicTangentBugPlanner<Space>::plan(const Query& q, const QueryOptions& query_options) {
  return impl_->plan(q, query_options);
}

template <class Space>
PlannerEntry<Space> tangent_bug_planner_entry() {
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
  return make_planner_entry<Space, TangentBugOptions>(
      "tangent-bug",
      "TangentBug: to the goal or the best discontinuity its range sensor sees, following a boundary where that stops "
      "bringing it nearer (Kamon, Rivlin & Rimon)",
      std::move(table), [](const typename Space::Problem& problem, const TangentBugOptions& o) {
        return std::make_unique<BasicTangentBugPlanner<Space>>(problem, o);
      });
}

template class BasicTangentBugPlanner<TranslatingRobot>;
template class BasicTangentBugPlanner<RoundRobot>;
template PlannerEntry<TranslatingRobot> tangent_bug_planner_entry<TranslatingRobot>();
template PlannerEntry<RoundRobot> tangent_bug_planner_entry<RoundRobot>();

}  // namespace polyplan
