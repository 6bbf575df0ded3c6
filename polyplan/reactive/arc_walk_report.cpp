// A Bug planner's walk along a boundary with arcs, reported (detail/arc_boundary.hpp): each run of
// the walk is a segment, or an arc where it followed an arc of the boundary; the whole walk is
// checked again run by run and at every joint, in CORE's numbers, with the same rules as the tangent
// paths (an arc checked open: its ends may touch the obstacles where two boundary pieces meet); its
// length is bounded outward (roadmaps/detail/certified_length.hpp). The points are printed as the
// doubles nearest them, moved a step of a double at a time to the free side while the exact rules
// find them inside an obstacle, so that a reader who tests the printed numbers finds them free.
#include <polyplan/plan/fact_points.hpp>
#include <polyplan/reactive/detail/arc_boundary.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/roadmaps/detail/certified_length.hpp>

#include <cmath>
#include <limits>

namespace polyplan::walk {
namespace {

using round_rules::sign_of;

// One run of the walk: straight, or along circles[*circle]; along the boundary or through the free
// space.
struct Run {
  AP from, to;
  std::optional<std::size_t> circle;
  bool counter_clockwise = true;
  bool along_boundary = false;
};

std::vector<Run> runs_of(const ArcBoundary& boundary, const std::vector<AP>& path,
                         const std::vector<std::optional<Along>>& along) {
  std::vector<Run> runs;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    Run run{path[k], path[k + 1], std::nullopt, true, along[k].has_value()};
    if (along[k] && boundary.piece(along[k]->edge).circle) {
      const ArcPiece& piece = boundary.piece(along[k]->edge);
      run.circle = piece.circle;
      run.counter_clockwise = piece.counter_clockwise == along[k]->forward;
    }
    runs.push_back(run);
  }
  return runs;
}

// The direction of travel along the run at its point x.
AP heading(const ArcBoundary& boundary, const Run& run, const AP& x) {
  if (!run.circle) return run.to - run.from;
  const AP r = x - boundary.circles()[*run.circle].centre;
  return run.counter_clockwise ? AP{-r.y, r.x} : AP{r.y, -r.x};
}

tangent::Arc arc_of(const ArcBoundary& boundary, const Run& run) {
  const tangent::Circle* circle = &boundary.circles()[*run.circle];
  return run.counter_clockwise ? tangent::Arc{circle, run.from, run.to} : tangent::Arc{circle, run.to, run.from};
}

std::optional<std::string> walk_blocked(const ArcBoundary& boundary, const std::vector<Run>& runs) {
  const auto& rules = boundary.rules();
  for (std::size_t k = 0; k <= runs.size(); ++k) {
    const AP& at = k < runs.size() ? runs[k].from : runs.back().to;
    std::optional<AP> in, out;
    if (k > 0) {
      const AP d = heading(boundary, runs[k - 1], at);
      in = AP{-d.x, -d.y};
    }
    if (k < runs.size()) out = heading(boundary, runs[k], at);
    if (auto why = rules.blocked_at(at, in, out)) return why;
    if (k == runs.size()) break;
    if (auto why = runs[k].circle ? tangent::arc_blocked(rules, arc_of(boundary, runs[k]), true)
                                  : rules.segment_blocked(runs[k].from, runs[k].to))
      return why;
  }
  return std::nullopt;
}

// x itself when it is rational (a corner of a polygon's Minkowski sum, a wall's end): the simplest
// rational near it — a convergent of the continued fraction of x to 80 bits, its denominator below
// 10^12 — is x exactly, as CORE decides.
std::optional<Rational> rational(const Algebraic& x) {
  const CORE::BigRat approximation = x.approx(CORE::extLong(80), CORE::extLong(1100)).BigRatValue();
  Rational rest(approximation.get_mp());
  mpz_class p0 = 0, q0 = 1, p1 = 1, q1 = 0;  // the convergents before
  for (int term = 0; term < 64 && q1 < mpz_class("1000000000000"); ++term) {
    mpz_class whole;
    mpz_fdiv_q(whole.get_mpz_t(), rest.get_num_mpz_t(), rest.get_den_mpz_t());
    const mpz_class p2 = whole * p1 + p0, q2 = whole * q1 + q0;
    const Rational candidate(p2, q2);
    if (algebraic(candidate) == x) return candidate;
    rest -= whole;
    if (rest == 0) break;
    rest = 1 / rest;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
  }
  return std::nullopt;
}

// x exactly where it is rational; else the doubles nearest it, moved towards `free_side` a step at
// a time while inside an obstacle.
ExactPoint printed(const round_rules::RoundRules<Rational>& rules, const AP& x, const AP& free_side) {
  if (auto px = rational(x.x))
    if (auto py = rational(x.y)) return {*px, *py};
  double d[2] = {approximate(x.x), approximate(x.y)};
  const int way[2] = {sign_of(free_side.x), sign_of(free_side.y)};
  const double inf = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 64 && rules.contact({Rational(d[0]), Rational(d[1])}).inside; ++step)
    for (int i = 0; i < 2; ++i)
      if (way[i] != 0) d[i] = std::nextafter(d[i], way[i] > 0 ? inf : -inf);
  return {Rational(d[0]), Rational(d[1])};
}

// Every point of the walk printed, its free side the sum of the left sides of the boundary runs
// that meet there (those through the free space cross it: their sides say nothing).
std::vector<ExactPoint> printed_path(const ArcBoundary& boundary, const std::vector<AP>& path,
                                     const std::vector<Run>& runs, const Query& query) {
  const round_rules::RoundRules<Rational> rules(boundary.world().cspace(), [](const Rational& q) { return q; });
  std::vector<ExactPoint> out;
  for (std::size_t k = 0; k < path.size(); ++k) {
    AP side{Algebraic(0), Algebraic(0)};
    for (const Run* run : {k > 0 ? &runs[k - 1] : nullptr, k < runs.size() ? &runs[k] : nullptr})
      if (run && run->along_boundary) {
        const AP d = heading(boundary, *run, path[k]);
        side = side + AP{-d.y, d.x};
      }
    out.push_back(printed(rules, path[k], side));
  }
  out.front() = query.start;  // exactly
  return out;
}

FactPoints doubles(const std::vector<AP>& points) {
  FactPoints out;
  for (const AP& p : points) out.push_back({approximate(p.x), approximate(p.y)});
  return out;
}

void mark(PlanReport<ExactPoint>& report, const std::vector<ExactPoint>& printed, const Query& query, bool arrived,
          const BasicWalk<AP>& walk) {
  using Kind = PlanMark<ExactPoint>::Kind;
  const auto exact = [](const std::vector<AP>& points) {
    std::vector<ExactPoint> out;
    for (const AP& p : points) out.push_back({Rational(approximate(p.x)), Rational(approximate(p.y))});
    return out;
  };
  report.recording.marks.push_back({Kind::lines, "m-line (start to goal)", {{query.start, query.goal}}});
  if (!arrived) report.recording.marks.push_back({Kind::lines, "the walk, stopped short of the goal", {printed}});
  if (!walk.hits.empty()) report.recording.marks.push_back({Kind::points, "hit points", {exact(walk.hits)}});
  if (!walk.leaves.empty()) report.recording.marks.push_back({Kind::points, "leave points", {exact(walk.leaves)}});
}

PathPiece path_piece(const ArcBoundary& boundary, const Run& run, const ExactPoint& from, const ExactPoint& to,
                     const tangent::LengthBounds& bounds) {
  PathPiece out;
  out.from = {to_double(from.x), to_double(from.y)};
  out.to = {to_double(to.x), to_double(to.y)};
  out.length = (bounds.lower + bounds.upper) / 2;
  if (run.circle) {
    const tangent::Circle& circle = boundary.circles()[*run.circle];
    out.kind = PathPiece::Kind::arc;
    out.centre = {to_double(circle.exact_centre.x), to_double(circle.exact_centre.y)};
    out.radius = to_double(circle.exact_radius);
    out.counter_clockwise = run.counter_clockwise;
  }
  return out;
}

}  // namespace

void report_walk(PlanReport<ExactPoint>& report, const ArcBoundary& boundary, const BasicWalk<AP>& walk,
                 const Query& query, bool arrived, bool record, const std::string& name) {
  std::vector<AP> path = walk.path;
  std::vector<std::optional<Along>> along = walk.along;
  const AP goal = ArcBoundary::point(query.goal);
  if (arrived && !(path.back() == goal)) path.push_back(goal), along.emplace_back();
  const std::vector<Run> runs = runs_of(boundary, path, along);
  std::vector<ExactPoint> printed = printed_path(boundary, path, runs, query);
  if (arrived) printed.back() = query.goal;
  tangent::LengthBounds total;
  std::vector<PathPiece> pieces;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto bounds = runs[k].circle ? tangent::arc_length(arc_of(boundary, runs[k]))
                                       : tangent::segment_length(runs[k].from, runs[k].to);
    total = total + bounds;
    pieces.push_back(path_piece(boundary, runs[k], printed[k], printed[k + 1], bounds));
  }
  total.lower = std::max(0.0, total.lower);
  report.facts.set(BugFacts::hits, doubles(walk.hits));
  report.facts.set(BugFacts::leaves, doubles(walk.leaves));
  report.facts.set(BugFacts::distance, (total.lower + total.upper) / 2);
  if (record) mark(report, printed, query, arrived, walk);
  // Checked, so that a mistake here is an answer that says so, never a path through an obstacle.
  const auto blocked = runs.empty() ? std::nullopt : walk_blocked(boundary, runs);
  if (!blocked) {
    report.path = printed;
    if (report.path.size() == 1) report.path.push_back(report.path.front());
    report.pieces = std::move(pieces);
  }
  if (!arrived) return;
  if (blocked) {
    report.fail(PlanStatus::not_found, name + "'s walk is not a valid motion (a bug of polyplan's): " + *blocked);
    return;
  }
  report.succeed();
  report.length = (total.lower + total.upper) / 2;
  report.facts.set(tangent::length_lower, total.lower);
  report.facts.set(tangent::length_upper, total.upper);
  report.certificate = {true,
                        "exact checks of the straight runs and of the arcs followed, in real algebraic "
                        "numbers (CORE), the length bounded outward"};
}

}  // namespace polyplan::walk
