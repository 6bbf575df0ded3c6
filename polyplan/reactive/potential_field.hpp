#pragma once
// The potential of a potential-field planner (Choset et al., "Principles of Robot Motion", ch. 4),
// its gradient and its Hessian at a point of the plane:
//
//   attractive  ½ ζ d²                      where d = |q − goal| ≤ d*
//               d* ζ d − ½ ζ d*²            beyond d* (conic: the pull is ζ d* whatever the distance)
//               ζ d                         everywhere when d* = 0 (the purely conic potential of the course's planning
//               problem set)
//   repulsive   ½ η (1/D − 1/Q*)²           of one obstacle at distance D ≤ Q*, 0 beyond Q*
//
// Value and gradient are continuous across d* and Q* (the Hessian jumps there, as the book's
// potentials do). The repulsive term reads the obstacle's nearest point: the gradient of D is the
// unit vector from it, and D's Hessian is (I − ∇D ∇Dᵀ)/D when that point is a corner of the
// obstacle, 0 when it lies inside an edge (D is then the distance to a line).
//
// These are doubles: a potential only steers. Every step a planner takes on it is checked exactly.
#include <polyplan/geometry/clearance.hpp>

#include <array>
#include <span>

namespace polyplan {

struct AttractiveParameters {
  double zeta = 1;    // ζ, the attraction's weight
  double d_star = 0;  // d*: quadratic within it, conic beyond; 0: conic everywhere
};

struct RepulsiveParameters {
  double eta = 1;     // η, the repulsion's weight
  double q_star = 1;  // Q*: an obstacle farther than this does not repel
};

// A symmetric 2 × 2 matrix.
struct Hessian2 {
  double xx = 0, xy = 0, yy = 0;
};

struct Potential {
  double value = 0;
  Vec2 gradient;
  Hessian2 hessian;
  friend Potential operator+(Potential a, const Potential& b) {
    return {a.value + b.value,
            {a.gradient.x + b.gradient.x, a.gradient.y + b.gradient.y},
            {a.hessian.xx + b.hessian.xx, a.hessian.xy + b.hessian.xy, a.hessian.yy + b.hessian.yy}};
  }
};

// Where an obstacle is nearest to a point: its distance, the nearest point, and whether that point
// is a corner (a vertex of the boundary) or lies inside an edge. A round obstacle's distance curves
// as a corner's does, about a centre `curve_offset` beyond the nearest point: a disc grown by the
// robot (its radius plus the robot's), a polygon's corner or a wall's end grown by the robot (the
// robot's radius), or, negative, the inside of disc bounds (minus its radius less the robot's).
struct NearestPoint {
  double distance = 0;
  Vec2 at;
  bool at_corner = false;
  double curve_offset = 0;  // 0: a bare corner, D the distance to the point itself
};

// The point of segment a-b nearest to q, and whether it is an end (a corner).
NearestPoint nearest_on_segment(Vec2 q, Vec2 a, Vec2 b);

// The nearest point of a polyline (its points in order; one point is a corner) to q. Throws
// std::invalid_argument for an empty polyline.
NearestPoint nearest_on_polyline(Vec2 q, std::span<const Vec2> line);

// The nearest point of a polygon's boundary (a closed ring, its vertices in order, not repeated)
// to q. Throws std::invalid_argument for an empty ring.
NearestPoint nearest_on_ring(Vec2 q, std::span<const Vec2> ring);

// A box's sides as walls, seen from q inside it: the nearest point of each (left, right, bottom,
// top; never a corner: D is the distance to a line).
struct SideBox {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};
std::array<NearestPoint, 4> nearest_on_sides(Vec2 q, const SideBox& box);

// The same obstacle grown by a disc robot's radius: `radius` nearer, its nearest point moved
// towards q (q outside the obstacle), and curving about the same centre.
NearestPoint grown(Vec2 q, NearestPoint nearest, double radius);

// At the goal the conic potential has no gradient (its minimum is a cone's point): 0 there, and
// the Hessian too.
Potential attractive_potential(Vec2 q, Vec2 goal, const AttractiveParameters& parameters);

// 0 beyond Q*; at D = 0 (on the obstacle) infinite in value, its gradient undefined: a caller
// must never ask there (the exact C-space keeps its steps off the obstacles).
Potential repulsive_potential(Vec2 q, const NearestPoint& nearest, const RepulsiveParameters& parameters);

// Its eigenvalues (smaller first) and what they make of a critical point: "minimum" (both > 0),
// "maximum" (both < 0), "saddle" (of opposite signs), "degenerate" (one is 0).
struct Eigenvalues {
  double smaller = 0, larger = 0;
};
Eigenvalues eigenvalues(const Hessian2& h);
const char* critical_point_kind(const Hessian2& h);

}  // namespace polyplan
