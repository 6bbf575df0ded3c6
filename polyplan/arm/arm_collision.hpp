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
// Not thread-safe: a checker keeps scratch buffers and a counter (mutable, for speed: no
// allocation per check). Use one checker per thread; construction is cheap.
#include <polyplan/arm/angles.hpp>
#include <polyplan/arm/arm.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/world.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <optional>
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

class ArmCollisionChecker {
 public:
  // Throws std::invalid_argument for an arm without links, a link that is not a positive finite
  // length, a negative or non-finite width, an obstacle with fewer than 3 vertices, or a
  // non-finite point. (The arm reader already guarantees all of that.)
  explicit ArmCollisionChecker(const ArmProblem&);
  ArmCollisionChecker(const Arm&, const std::vector<PolygonWithHoles>& obstacles, const std::vector<Eigen::Vector2d>& points);
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

  // Configurations checked so far (is_free and first_contact calls), for the planners' counts.
  std::size_t checks() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
