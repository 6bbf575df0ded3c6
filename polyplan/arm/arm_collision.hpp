#pragma once
// Is a configuration of the arm free? Exact predicates on the arm's computed coordinates.
//
// The convention (deliberately conservative: touching counts as collision):
//  - A link is closed: the segment between its joints (link_width 0) or the closed rectangle
//    w wide on that segment (its four corners as link_outline computes them, in doubles).
//  - An obstacle polygon is closed: boundary and interior; its holes' interiors are free.
//  - A configuration collides when a link meets an obstacle polygon, or contains an obstacle
//    point (a point on the link's boundary counts), or — with Arm::self_collision — meets a link
//    with which it shares no joint. Adjacent links share a joint and never count.
//
// Kinematic coordinates are doubles (cos and sin make them irrational by nature); everything
// decided on them is decided by CGAL Epick's exact predicates (orientation, segment intersection,
// point in polygon), never by an epsilon. Obstacle vertices are the problem's exact rationals
// rounded to the nearest double (geometry/rational.hpp to_double) once, at construction. A
// rectangle so thin that its double corners are not strictly convex is checked as its segment.
//
// Clearances (for certified motions, arm_motion.hpp) are lower bounds of distances from the true
// arm — the same link lengths and width, placed with the real cos and sin of the real sums of the
// angles — to the file's obstacles — polygons with their exact rational vertices, points as the
// doubles the file's numbers round to: 0 when the computed shapes meet (decided by the exact test
// above, never by a tolerance); otherwise the distance between the computed shapes, bounded from
// below in interval arithmetic rounded outward (CGAL's Interval_nt), less a radius that encloses
// the true arm around the computed one (arm/detail/true_arm_bounds.hpp, also interval arithmetic)
// and the obstacles' vertices around their doubles, clamped at 0. No ad-hoc margin: each clearance
// is a proof. docs/certification.md gives the argument.
//
// Not thread-safe: a checker keeps scratch buffers and a counter (mutable, for speed: no
// allocation per check). Use one checker per thread; construction is cheap.
#include <polyplan/arm/arm.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/world.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace polyplan {

// What a colliding configuration hits. `link` is 0-based (links[link]); describe() numbers links
// from 1 as the prose does ("link 1" touches the base) and obstacles and points by their file index.
struct ArmContact {
  std::size_t link = 0;
  enum class With { polygon, point, link } with = With::polygon;
  std::size_t index = 0;  // obstacles[index], points[index], or the other link (0-based)
  // "link 2 meets obstacles[0]", "link 1 meets points[4]", "link 1 meets link 3".
  std::string describe() const;
};

// Lower bounds of the distances of one configuration, split by what they are to (see
// ArmCollisionChecker::clearances). +infinity where there is nothing to measure to.
struct ArmClearances {
  std::vector<double> links;  // [k]: links[k] to every obstacle polygon and point
  // [k * n + m] for n links: links[k] to links[m], symmetric, when they may collide (self-collision
  // on and no shared joint, |k − m| ≥ 2); +infinity for every other pair. Empty without self-collision.
  std::vector<double> pairs;
  std::optional<ArmContact> contact;  // the configuration's first contact (as first_contact), if any
};

// What clearances are for. `reading`: values a caller reads, each the interval bound (within a
// few ulps of the true distance). `stepping`: the lengths of safe steps (arm_motion.hpp), for which
// far from contact the fast distance less its written error bound will do (docs/certification.md:
// it falls short of the interval bound by at most 2^-9 of the clearance); nearer contact the
// interval bound is computed all the same. Both are proofs.
enum class ClearanceUse { reading, stepping };

// The result of ArmCollisionChecker::safe_step.
struct ArmSafeStep {
  double step = 0;                    // 0 when the configuration collides
  std::optional<ArmContact> contact;  // the first contact (as first_contact) when it collides
};

class ArmCollisionChecker {
 public:
  // Throws std::invalid_argument for an arm without links, a link that is not a positive finite
  // length, a negative or non-finite width, an obstacle with fewer than 3 vertices, or a
  // non-finite point. (The arm reader already guarantees all of that.)
  explicit ArmCollisionChecker(const ArmProblem&);
  ArmCollisionChecker(const Arm&, const std::vector<PolygonWithHoles>& obstacles,
                      const std::vector<Eigen::Vector2d>& points);
  ~ArmCollisionChecker();
  // Movable, not copyable; a moved-from checker may only be destroyed or assigned to.
  ArmCollisionChecker(ArmCollisionChecker&&) noexcept;
  ArmCollisionChecker& operator=(ArmCollisionChecker&&) noexcept;

  const Arm& arm() const;

  // Throws std::invalid_argument when the angle count is not the arm's or an angle is not finite.
  bool is_free(const JointAngles&) const;
  // The first contact in this order: links from the base outwards; for each link the obstacle
  // polygons in order, then the points in order, then (self-collision) the later links.
  std::optional<ArmContact> first_contact(const JointAngles&) const;

  // Lower bounds of each true link's distance to what it may collide with (0 when it touches or
  // meets something, or may come within the rounding of it), for the configuration q; out[k] for links[k] (resized to
  // the link count): the minimum over the obstacle polygons, the points and, with self-collision, the links it shares
  // no joint with. +infinity when nothing is within reach. Throws like is_free.
  void clearances(const JointAngles& q, std::vector<double>& out) const;
  // The same split into obstacle and link-pair clearances, with the first contact. A clearance of
  // at least `enough` may be reported as any value of at least `enough`: what lies farther away is
  // not measured (a grid planner needs clearances only up to a step's sweep).
  void clearances(const JointAngles& q, ArmClearances& out, double enough = std::numeric_limits<double>::infinity(),
                  ClearanceUse use = ClearanceUse::reading) const;

  // Conservative advancement's step (arm_motion.hpp), for the configuration q, or for every
  // configuration within spread[j] radians of q in each joint j (spread empty: q alone; a motion's
  // computed configuration lies that close to the true one). When q collides: step 0 and its
  // first contact. Otherwise a lower bound h of how long the true arm stays free, at most
  // `horizon`, when every point of links[k] moves at most link_speed[k] per unit of time and,
  // with self-collision, every point of links[m] relative to links[k] (in the frame of links[k])
  // at most pair_speed[k * n + m] for m ≥ k + 2 (speeds: upper bounds):
  //   min(horizon, min_k c_k / link_speed[k], min_{k, m} c_km / pair_speed[k * n + m]),
  // each quotient rounded down, with c / 0 = +infinity for c > 0 and 0 for c = 0 (a clearance of
  // 0 proves nothing, even for something that does not move). Every configuration reached within
  // a time below h is free. Only what can lower the minimum is measured: obstacles whose bounding
  // box is farther away are skipped. Throws std::invalid_argument like is_free, and for speed or
  // spread lists of the wrong size (pair_speed: n * n entries, or none without self-collision).
  ArmSafeStep safe_step(const JointAngles& q, std::span<const double> link_speed, std::span<const double> pair_speed,
                        double horizon, std::span<const double> spread = {}) const;

  // Configurations checked so far (is_free, first_contact, clearances and safe_step calls), for the
  // planners' counts.
  std::size_t checks() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Why the query cannot be planned for the checker's arm: angles of the wrong count ("the query
// easy has 2 start and 3 goal angles for an arm of 3 joints") or a start or goal that collides
// ("the start collides: link 2 meets obstacles[0]"); nullopt when both are free. A goal in the
// workspace (goal_point) is not tested here — its goal set holds free configurations only — but a
// query with both goal angles and a goal point, or a goal point that is not finite, is refused.
// Planners' why_not.
std::optional<std::string> query_not_free(const ArmCollisionChecker&, const ArmQuery&);

}  // namespace polyplan
