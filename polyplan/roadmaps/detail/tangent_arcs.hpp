#pragma once
// The circles a shortest path of a point or disc robot bends around, their common tangents and the
// exact test of an arc along one (roadmaps/tangent_visibility.hpp). A shortest path among discs,
// walls and polygons, each grown by the robot's radius r, is made of straight segments tangent to
// circles and of arcs along them: the discs grown by r, and every vertex of a polygon or a wall
// with radius r (radius 0 for a point robot: the path only turns there). All of it in real
// algebraic numbers: a tangent point is a + b√c.
#include <polyplan/roadmaps/detail/algebraic.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::tangent {

struct Circle {
  AlgebraicPoint centre;
  Algebraic radius;
  ExactPoint exact_centre;  // the same centre and radius as rationals: for the certified lengths
  Rational exact_radius;    // and the printed points
  std::string name;         // "discs[2]", "obstacles[0] vertex 3", for messages
};

// The circles of a round C-space: every point core with its radius, and every vertex of a wall or
// a polygon (outer ring and holes) with the core's radius (0: a corner the path turns at).
std::vector<Circle> circles_of(const RoundCSpace& space);

// A straight motion from a touching point of one circle to one of another.
struct Tangent {
  AlgebraicPoint from, to;
};

// The common tangents of a and b, each from a's touching point to b's: up to four (two outer,
// two inner), two from a point (radius 0) to a circle, one between two points; none for
// concentric circles.
std::vector<Tangent> common_tangents(const Circle& a, const Circle& b);

// The arc of `circle` from `from` counter-clockwise to `to`, both on it (from == to: the point).
struct Arc {
  const Circle* circle = nullptr;
  AlgebraicPoint from, to;
};

// Whether the direction u from the arc's centre points into the closed arc.
bool spans(const Arc& arc, const AlgebraicPoint& u);

// Whether direction u comes strictly before v counter-clockwise from direction a (a itself first):
// the order of the points on a circle.
bool turns_before(const AlgebraicPoint& a, const AlgebraicPoint& u, const AlgebraicPoint& v);

// Why the robot's centre may not travel along the arc, or none. It may not come nearer an obstacle's
// core than the obstacle's radius, nor touch an obstacle other than the circle's own (the disc, or
// the edges and wall pieces ending at the corner): an arc touching another obstacle passes where two
// touch, a passage of zero width. Nor may it touch or leave the bounds. An open arc (`open`: the
// Bug planners' walk along the free space's boundary, whose pieces end where obstacles meet) may
// touch anything at its ends, and runs along the bounds where it is an arc of their circle.
std::optional<std::string> arc_blocked(const round_rules::RoundRules<Algebraic>& rules, const Arc& arc,
                                       bool open = false);

// A piece of a path: the segment from `from` to `to`, or the arc of circles[*circle] between them,
// turning counter-clockwise or not — a tangent path's pieces, and the Bug planners' boundary.
struct CirclePiece {
  AlgebraicPoint from, to;
  std::optional<std::size_t> circle;
  bool counter_clockwise = true;
};

// The direction of travel along the piece at its point x.
AlgebraicPoint heading(const CirclePiece& piece, const AlgebraicPoint& x, const std::vector<Circle>& circles);
// The piece's arc as Arc takes it (counter-clockwise from its first end).
Arc arc_of(const CirclePiece& piece, const std::vector<Circle>& circles);

// Why the path of pieces is blocked, or none: every piece (its arcs as arc_blocked checks them,
// `open` or not) and every joint, with the direction the path arrives from and the one it leaves
// along. The exact check of a path whose points are irrational. `covers`, if given, holds for each
// piece one that contains it, checked in its place (a walk along the free space's boundary: the
// boundary piece it runs along, whose ends are simpler numbers than a point the walk stopped at).
std::optional<std::string> path_blocked(const round_rules::RoundRules<Algebraic>& rules,
                                        const std::vector<CirclePiece>& pieces, const std::vector<Circle>& circles,
                                        bool open = false, const std::vector<CirclePiece>* covers = nullptr);

// How a path's point on `circle` is printed: the centre itself for a circle of radius 0 (a corner);
// a touching point on a circle of radius ρ > 0 (irrational) as a point of doubles next to it, moved
// outwards a step of a double at a time while it is not at least ρ·(1 + 1e-15) from the centre: a
// reader who tests the printed numbers exactly finds them clear of the disc, and the segment
// between two of them too (turning a tangent by a double's step brings it nearer the centre only
// by the square of that).
ExactPoint printed_point(const AlgebraicPoint& p, const Circle& circle);

}  // namespace polyplan::tangent
