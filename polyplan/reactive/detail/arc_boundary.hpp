#pragma once
// The free space's boundary of a round world whose C-obstacles have arcs (discs, a disc robot,
// disc bounds), as the Bug planners walk it: cycles of pieces — segments and arcs of circles —
// each with the free space on its left, in real algebraic numbers (CORE), since the points where
// a grown edge meets a circle are irrational. Built as reactive/round_boundary.cpp builds the
// straight-edged one: every candidate piece (each polygon edge or wall side moved out by the
// core's radius, each disc and each grown corner's whole circle, the bounds) cut wherever it meets
// another, kept where the exact rules find its midpoint free with the way to its left open, and
// linked as a face of an arrangement is walked. Only the Bug planners' units include this header
// (bug1, bug2 and tangent-bug's).
#include <polyplan/reactive/walk_report.hpp>
#include <polyplan/roadmaps/detail/tangent_arcs.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::walk {

using AP = AlgebraicPoint;

// A piece of the boundary: a segment, or an arc of one of the boundary's circles.
using ArcPiece = tangent::CirclePiece;

// "(x, y)" with six decimals, as walk::text prints a rational point.
std::string text(const AP& p);

class ArcBoundary {
 public:
  using Point = AP;
  // The world must outlive the boundary.
  explicit ArcBoundary(const RoundWorld& world);

  const std::vector<tangent::Circle>& circles() const { return circles_; }
  const std::vector<std::vector<ArcPiece>>& cycles() const { return cycles_; }
  const round_rules::RoundRules<Algebraic>& rules() const { return rules_; }
  const RoundWorld& world() const { return *world_; }
  const ArcPiece& piece(Edge e) const { return cycles_[e.cycle][e.index % cycles_[e.cycle].size()]; }
  // The direction of travel along `piece` at its point x.
  AP heading(const ArcPiece& piece, const AP& x) const { return tangent::heading(piece, x, circles_); }

  // What the Bug planners ask of a boundary, as walk::Boundary answers it for straight edges.
  static AP point(const ExactPoint& p) { return algebraic(p); }
  static Algebraic squared_distance(const AP& a, const AP& b) { return round_rules::squared(a - b); }
  std::optional<std::string> query_not_free(const Query& query) const;
  std::optional<AP> first_hit(const AP& from, const AP& to) const;
  std::optional<Edge> edge_at(const AP& p, const AP& heading) const;
  double perimeter(std::size_t cycle) const;
  std::size_t crossings(std::size_t cycle, const AP& start, const AP& goal) const;
  std::size_t size(std::size_t cycle) const { return cycles_[cycle].size(); }
  const AP& start(Edge e) const { return piece(e).from; }
  const AP& end(Edge e) const { return piece(e).to; }
  std::vector<AP> line_points(Edge e, const AP& a, const AP& b, const AP& s, const AP& g) const;
  int side(Edge e, const AP& x, const AP& p) const;
  AP nearest(Edge e, const AP& a, const AP& b, const AP& p) const;
  double length(Edge e, const AP& a, const AP& b) const;
  static Algebraic number(const Rational& q) { return algebraic(q); }

  // What TangentBug asks besides: whether the straight way from one point to another is free (both
  // ends may touch the boundary); whether, walking the piece from its start, x comes strictly before
  // y (both on it); the points of the piece's part from a to b (a first along it) on the circle
  // (centre, radius), and those where a line from p touches the piece's circle, in walking order.
  bool sees(const AP& from, const AP& to) const;
  bool before(Edge e, const AP& x, const AP& y) const { return before(piece(e), x, y); }
  std::vector<AP> circle_points(Edge e, const AP& a, const AP& b, const AP& centre, const Algebraic& radius) const;
  std::vector<AP> touching_points(Edge e, const AP& a, const AP& b, const AP& p) const;

 private:
  // Whether x lies on the piece's part from a to b (all three on its line or circle).
  bool within(const ArcPiece& piece, const AP& a, const AP& b, const AP& x) const;
  // Whether, walking the piece from its start, x comes strictly before y (both on it).
  bool before(const ArcPiece& piece, const AP& x, const AP& y) const;
  // Those of `points` on the piece's part from a to b, once each, in walking order.
  std::vector<AP> in_walking_order(const ArcPiece& piece, const AP& a, const AP& b,
                                   const std::vector<AP>& points) const;

  const RoundWorld* world_;
  round_rules::RoundRules<Algebraic> rules_;
  std::vector<tangent::Circle> circles_;
  std::vector<std::vector<ArcPiece>> cycles_;
};

// The walk reported as walk_report.hpp reports a straight-edged one, its runs along arcs as arcs:
// the path's pieces (segments and arcs, the points printed as doubles on the free side), its length
// bounded outward, the whole walk checked exactly in CORE's numbers.
void report_walk(PlanReport<ExactPoint>& report, const ArcBoundary& boundary, const BasicWalk<AP>& walk,
                 const Query& query, bool arrived, bool record, const std::string& name);

}  // namespace polyplan::walk
