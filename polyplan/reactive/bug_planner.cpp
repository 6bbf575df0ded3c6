#include <polyplan/reactive/bug_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace polyplan {
namespace {

using Point = ExactPoint;

Rational cross(const Point& o, const Point& a, const Point& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
Rational dot(const Point& o, const Point& a, const Point& b) { return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y); }
Rational squared(const Point& a, const Point& b) { return dot(a, b, b); }
Point along(const Point& a, const Point& b, const Rational& t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }
double length(const Point& a, const Point& b) { return std::sqrt(to_double(squared(a, b))); }

std::string text(const Point& p) { return "(" + std::to_string(to_double(p.x)) + ", " + std::to_string(to_double(p.y)) + ")"; }

// The parameters t ∈ [0, 1] of p + t(q − p) where the segment a-b meets the segment p-q (both
// ends of a collinear overlap), appended to `out`. p ≠ q.
void meetings(const Point& p, const Point& q, const Point& a, const Point& b, std::vector<Rational>& out) {
  const Rational da = cross(p, q, a), db = cross(p, q, b), pq = squared(p, q);
  const auto keep = [&](const Point& x) {
    const Rational t = dot(p, x, q) / pq;
    if (t >= 0 && t <= 1) out.push_back(t);
  };
  if (da == 0 && db == 0) {
    keep(a), keep(b);
    return;
  }
  if ((da > 0 && db > 0) || (da < 0 && db < 0)) return;
  const Point x = along(a, b, da / (da - db));  // on the line p-q
  const Rational s = dot(a, x, b), ab = squared(a, b);
  if (s >= 0 && s <= ab) keep(x);
}

// The free space's boundary cycles, each walked with the free space on its left.
std::vector<std::vector<Point>> boundary_cycles(const CSpace& cspace) {
  std::vector<std::vector<Point>> cycles;
  const auto add = [&](const Ring& ring, bool free_inside) {
    if (ring.size() < 2) return;
    Rational area = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) area += cross({0, 0}, ring[i], ring[(i + 1) % ring.size()]);
    std::vector<Point> cycle(ring.begin(), ring.end());
    if ((area > 0) != free_inside) std::reverse(cycle.begin(), cycle.end());
    cycles.push_back(std::move(cycle));
  };
  for (const FreeComponent& c : cspace.free_components()) {
    add(c.outer, true);
    for (const Ring& hole : c.holes) add(hole, false);
  }
  return cycles;
}

struct Edge {
  std::size_t cycle = 0, index = 0;  // from cycles[cycle][index] to the next vertex
};

}  // namespace

struct BugPlanner::Impl {
  const CSpace* cspace;
  BugKind kind;
  BugOptions options;
  std::vector<std::vector<Point>> cycles;

  const Point& vertex(std::size_t cycle, std::size_t i) const { return cycles[cycle][i % cycles[cycle].size()]; }

  // Where the straight way from `from` to `goal` first stops being free (from itself, when it
  // cannot head for the goal at all); nullopt when the whole way is free.
  std::optional<Point> first_hit(const Point& from, const Point& goal) const {
    if (check_segment(*cspace, from, goal).valid) return std::nullopt;
    std::vector<Rational> ts{0, 1};
    for (std::size_t c = 0; c < cycles.size(); ++c)
      for (std::size_t i = 0; i < cycles[c].size(); ++i) meetings(from, goal, vertex(c, i), vertex(c, i + 1), ts);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k)
      if (!check_segment(*cspace, from, along(from, goal, ts[k + 1])).valid) return along(from, goal, ts[k]);
    return from;  // not reached: the whole way would be free
  }

  // The boundary edge the point lies on, starting there or passing through it.
  std::optional<Edge> edge_at(const Point& p) const {
    for (std::size_t c = 0; c < cycles.size(); ++c)
      for (std::size_t i = 0; i < cycles[c].size(); ++i) {
        const Point &a = vertex(c, i), &b = vertex(c, i + 1);
        if (p == b || cross(a, b, p) != 0) continue;
        const Rational s = dot(a, p, b);
        if (s >= 0 && s < squared(a, b)) return Edge{c, i};
      }
    return std::nullopt;
  }

  double perimeter(std::size_t cycle) const {
    double sum = 0;
    for (std::size_t i = 0; i < cycles[cycle].size(); ++i) sum += length(vertex(cycle, i), vertex(cycle, i + 1));
    return sum;
  }

  // How often the m-line start-goal meets a cycle (distinct points).
  std::size_t crossings(std::size_t cycle, const Point& start, const Point& goal) const {
    std::vector<Rational> ts;
    for (std::size_t i = 0; i < cycles[cycle].size(); ++i) meetings(start, goal, vertex(cycle, i), vertex(cycle, i + 1), ts);
    std::sort(ts.begin(), ts.end());
    return static_cast<std::size_t>(std::unique(ts.begin(), ts.end()) - ts.begin());
  }

  // Bug2's walk round the boundary from the hit point: the first m-line point nearer the goal from
  // which it can head for it; nullopt when the walk comes back to the hit point.
  std::optional<Point> follow_to_leave(const Point& hit, Edge edge, const Query& q, std::vector<Point>& path) const {
    const Rational hit_distance = squared(hit, q.goal);
    const std::size_t n = cycles[edge.cycle].size(), hit_edge = edge.index;
    Point at = hit;
    for (std::size_t walked = 0; walked <= n; ++walked, ++edge.index) {
      const bool back = walked > 0 && edge.index % n == hit_edge;  // round again onto the hit point's edge
      const Point& end = back ? hit : vertex(edge.cycle, edge.index + 1);
      std::vector<Rational> ts;
      if (!(at == end)) meetings(at, end, q.start, q.goal, ts);
      std::sort(ts.begin(), ts.end());
      for (const Rational& t : ts) {
        const Point x = along(at, end, t);
        if (!(squared(x, q.goal) < hit_distance)) continue;
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
    const std::size_t n = cycles[edge.cycle].size();
    // The loop: hit, the vertices after it, hit again.
    std::vector<Point> loop{hit};
    for (std::size_t k = 1; k <= n; ++k) loop.push_back(vertex(edge.cycle, edge.index + k));
    if (!(loop.back() == hit)) loop.push_back(hit);
    std::vector<double> arc{0};
    for (std::size_t k = 1; k < loop.size(); ++k) arc.push_back(arc.back() + length(loop[k - 1], loop[k]));
    // The nearest point: on each edge the foot of the perpendicular from the goal, or an end.
    Point nearest = hit;
    Rational best = squared(hit, q.goal);
    std::size_t on = 0;
    double at_arc = 0;
    for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
      const Point &a = loop[k], &b = loop[k + 1];
      if (a == b) continue;
      const Rational t = std::clamp(Rational(dot(a, q.goal, b) / squared(a, b)), Rational(0), Rational(1));
      const Point foot = along(a, b, t);
      if (squared(foot, q.goal) < best) best = squared(foot, q.goal), nearest = foot, on = k, at_arc = arc[k] + length(a, foot);
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
};

BugPlanner::BugPlanner(const CSpace& cspace, BugKind kind, BugOptions options)
    : impl_(std::make_unique<Impl>(Impl{&cspace, kind, options, boundary_cycles(cspace)})) {}

BugPlanner::~BugPlanner() = default;

PlanReport<ExactPoint> BugPlanner::plan(const Query& q, const QueryOptions&) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  const char* name = r.kind == BugKind::bug1 ? "bug1" : "bug2";
  facts.set("roadmap.kind", name);
  std::vector<Point> path{q.start};
  std::string hits, leaves;
  std::set<std::size_t> met;
  std::size_t hit_count = 0;
  const auto finish = [&] {
    facts.set("bug.hits", hits);
    facts.set("bug.leaves", leaves);
    const double d = length(q.start, q.goal);
    double bound = d;
    for (const std::size_t c : met)
      bound += r.kind == BugKind::bug1 ? 1.5 * r.perimeter(c) : 0.5 * static_cast<double>(r.crossings(c, q.start, q.goal)) * r.perimeter(c);
    facts.set("bug.distance", euclidean_length(path));
    facts.set("bug.bound", bound);
    facts.set("query_seconds", querying.seconds());
    return std::move(report);
  };
  if (auto why = r.cspace->query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish();
  }
  Point at = q.start;
  for (;;) {
    const auto hit = r.first_hit(at, q.goal);
    if (!hit) break;
    if (++hit_count > r.options.max_hits) {
      facts.set("stopped_by", "hit limit");
      report.fail(PlanStatus::limit, "the hit limit (" + std::to_string(r.options.max_hits) + ") ended the walk at " + text(at));
      return finish();
    }
    if (!(*hit == at)) path.push_back(*hit);
    hits += (hits.empty() ? "" : " ") + text(*hit);
    const auto edge = r.edge_at(*hit);
    if (!edge) throw std::logic_error("bug planner: a hit point " + text(*hit) + " on no boundary edge");
    met.insert(edge->cycle);
    std::optional<Point> leave;
    if (r.kind == BugKind::bug2) {
      leave = r.follow_to_leave(*hit, *edge, q, path);
    } else {
      const Point nearest = r.go_round(*hit, *edge, q, path);
      const auto blocked = r.first_hit(nearest, q.goal);
      if (!blocked || !(*blocked == nearest)) leave = nearest;
    }
    if (!leave) {
      report.fail(PlanStatus::no_path, std::string(r.kind == BugKind::bug1 ? "round the obstacle hit at " + text(*hit) + ", the point nearest the goal cannot head for it"
                                                                           : "the walk round the obstacle came back to its hit point " + text(*hit) + " without a leave point") +
                                           ": the goal is unreachable (" + name + " is complete)");
      return finish();
    }
    leaves += (leaves.empty() ? "" : " ") + text(*leave);
    at = *leave;
  }
  if (!(path.back() == q.goal)) path.push_back(q.goal);
  if (path.size() == 1) path.push_back(q.goal);
  report.succeed();
  report.path = path;
  report.length = euclidean_length(report.path);
  report.certificate = {true, "exact path check (arrangement zone walk) of the straight runs and the boundary edges followed"};
  // Every point is exact and every run straight or along an edge, so this holds; checked all the
  // same, so that a mistake here is an answer that says so, never a path through an obstacle.
  const PathCheck check = check_path(*r.cspace, report.path);
  if (!check.valid) {
    report.path.clear();
    report.length = 0;
    report.certificate = {};
    report.fail(PlanStatus::not_found, std::string(name) + "'s walk is not a valid motion (a bug of polyplan's): " + check.reason);
  }
  return finish();
}

PlannerEntry<TranslatingRobot> bug_planner_entry(BugKind kind) {
  OptionTable<BugOptions> table;
  table.add("max-hits", &BugOptions::max_hits, "obstacles hit before the walk stops with status limit");
  const bool one = kind == BugKind::bug1;
  return make_planner_entry<TranslatingRobot, BugOptions>(
      one ? "bug1" : "bug2",
      one ? "Bug1: to the goal, round each obstacle hit, leaving from its point nearest the goal (Lumelsky & Stepanov)"
          : "Bug2: along the start-goal line, round each obstacle hit until the line is met nearer the goal (Lumelsky & Stepanov)",
      std::move(table), [kind](const CSpace& cspace, const BugOptions& o) { return std::make_unique<BugPlanner>(cspace, kind, o); });
}

}  // namespace polyplan
