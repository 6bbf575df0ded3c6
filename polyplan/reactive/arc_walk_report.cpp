// A Bug planner's walk along a boundary with arcs, reported (detail/arc_boundary.hpp): each run of
// the walk is a segment, or an arc where it followed an arc of the boundary; the whole walk is
// checked again run by run (a run along the boundary as the boundary piece it follows) and at every joint by the
// tangent paths' own check (tangent::path_blocked, its arcs open: their ends may touch the obstacles where two boundary
// pieces meet); its length is bounded outward and its pieces reported as theirs are
// (roadmaps/detail/certified_length.hpp). The points are printed as the doubles nearest them, moved a step of a double
// at a time to the free side while the exact rules find them inside an obstacle, so that a reader who tests the printed
// numbers finds them free.
#include <polyplan/plan/fact_points.hpp>
#include <polyplan/reactive/detail/arc_boundary.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/roadmaps/detail/certified_length.hpp>

#include <cmath>
#include <limits>

namespace polyplan::walk {
namespace {

using round_rules::sign_of;

// The walk's runs: run k from path[k] to path[k + 1], straight, or along the circle of the
// boundary piece it followed (a segment of the boundary is a straight run too).
std::vector<tangent::CirclePiece> runs_of(const ArcBoundary& boundary, const std::vector<AP>& path,
                                          const std::vector<std::optional<Along>>& along) {
  std::vector<tangent::CirclePiece> runs;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    tangent::CirclePiece run{path[k], path[k + 1], std::nullopt, true};
    if (along[k]) {
      const ArcPiece& piece = boundary.piece(along[k]->edge);
      run.circle = piece.circle;
      run.counter_clockwise = piece.counter_clockwise == along[k]->forward;
    }
    runs.push_back(run);
  }
  return runs;
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
    // Equal as CORE decides, and as its own 80-bit approximation agrees: a guard, since CORE once
    // found a deep number equal to a rational 4.7e-9 from its approximation (the walk's printing
    // then takes the doubles nearest it instead, as for any irrational point).
    if (algebraic(candidate) == x && abs(candidate - Rational(approximation.get_mp())) <= abs(candidate) * 1e-20)
      return candidate;
    rest -= whole;
    if (rest == 0) break;
    rest = 1 / rest;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
  }
  return std::nullopt;
}

// The obstacle circle (a disc, a grown corner) x lies on or next to, judged in doubles, if any: it
// only chooses how a point is printed (which point is free, the exact contact test decides).
const tangent::Circle* circle_at(const ArcBoundary& boundary, const AP& x) {
  const double px = approximate(x.x), py = approximate(x.y);
  for (const tangent::Circle& c : boundary.circles()) {
    const double r = approximate(c.radius);
    if (r > 0 && c.name != "the bounds" &&
        std::abs(std::hypot(px - approximate(c.centre.x), py - approximate(c.centre.y)) - r) <= 1e-9 * (1 + r))
      return &c;
  }
  return nullptr;
}

// On an obstacle's circle, x clear of it as the tangent paths print a touching point
// (tangent::printed_point: so that the straight runs between printed points are free too); else x
// exactly where it is rational, or the doubles nearest it; then moved towards `free_side` a step at
// a time while inside an obstacle.
ExactPoint printed(const ArcBoundary& boundary, const round_rules::RoundRules<Rational>& rules, const AP& x,
                   const AP& free_side) {
  double d[2] = {approximate(x.x), approximate(x.y)};
  if (const tangent::Circle* circle = circle_at(boundary, x)) {
    const ExactPoint clear = tangent::printed_point(x, *circle);
    d[0] = to_double(clear.x), d[1] = to_double(clear.y);
  } else if (auto px = rational(x.x)) {
    if (auto py = rational(x.y)) return {*px, *py};
  }
  const int way[2] = {sign_of(free_side.x), sign_of(free_side.y)};
  const double inf = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 64 && rules.contact({Rational(d[0]), Rational(d[1])}).inside; ++step)
    for (int i = 0; i < 2; ++i)
      if (way[i] != 0) d[i] = std::nextafter(d[i], way[i] > 0 ? inf : -inf);
  return {Rational(d[0]), Rational(d[1])};
}

// Every point of the walk printed, its free side the sum of the free sides of the boundary runs
// that meet there (the left walking forwards, the right walking back) (those through the free space cross it: their
// sides say nothing).
std::vector<ExactPoint> printed_path(const ArcBoundary& boundary, const std::vector<AP>& path,
                                     const std::vector<tangent::CirclePiece>& runs,
                                     const std::vector<std::optional<Along>>& along, const Query& query) {
  const round_rules::RoundRules<Rational> rules(boundary.world().cspace(), [](const Rational& q) { return q; });
  std::vector<ExactPoint> out;
  for (std::size_t k = 0; k < path.size(); ++k) {
    AP side{Algebraic(0), Algebraic(0)};
    for (const std::size_t r : {k - 1, k})  // the runs arriving and leaving (k - 1 wraps past the end at k = 0)
      if (r < runs.size() && along[r]) {
        const AP d = boundary.heading(runs[r], path[k]);  // the free side: left walking forwards, right back
        side = side + (along[r]->forward ? AP{-d.y, d.x} : AP{d.y, -d.x});
      }
    out.push_back(printed(boundary, rules, path[k], side));
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

}  // namespace

void report_walk(PlanReport<ExactPoint>& report, const ArcBoundary& boundary, const BasicWalk<AP>& walk,
                 const Query& query, bool arrived, bool record, const std::string& name) {
  std::vector<AP> path = walk.path;
  std::vector<std::optional<Along>> along = walk.along;
  const AP goal = ArcBoundary::point(query.goal);
  if (arrived && !(path.back() == goal)) path.push_back(goal), along.emplace_back();
  const std::vector<tangent::CirclePiece> runs = runs_of(boundary, path, along);
  std::vector<ExactPoint> printed = printed_path(boundary, path, runs, along, query);
  if (arrived) printed.back() = query.goal;
  tangent::LengthBounds total;
  std::vector<PathPiece> pieces;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto bounds = tangent::length_bounds(runs[k], boundary.circles());
    total = total + bounds;
    pieces.push_back(tangent::path_piece(runs[k], boundary.circles(), printed[k], printed[k + 1], bounds));
  }
  total.lower = std::max(0.0, total.lower);
  report.facts.set(BugFacts::hits, doubles(walk.hits));
  report.facts.set(BugFacts::leaves, doubles(walk.leaves));
  report.facts.set(BugFacts::distance, (total.lower + total.upper) / 2);
  if (record) mark(report, printed, query, arrived, walk);
  // Checked, so that a mistake here is an answer that says so, never a path through an obstacle.
  // A run along the boundary is checked as the whole boundary piece it follows: the same proof (the
  // run lies on the piece), and the piece's ends are where world curves meet, numbers of low degree,
  // while a point a walk stopped at may be a touching point from a touching point (tangent-bug):
  // CORE decides those only slowly where they touch.
  std::vector<tangent::CirclePiece> covers = runs;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (along[k]) covers[k] = boundary.piece(along[k]->edge);
  const auto blocked =
      runs.empty() ? std::nullopt : tangent::path_blocked(boundary.rules(), runs, boundary.circles(), true, &covers);
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
