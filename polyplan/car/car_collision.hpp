#pragma once
// Whether a steered car's body is free at a pose and along a segment, proved, never sampled. A
// segment is a translation (straight) or a rotation about the turning centre (arc), so what the
// body sweeps can be enclosed: for a straight, the hull of each convex piece of the body at both
// ends (exactly the sweep); for an arc, the hull of each piece's vertices at both ends of the arc
// and the apexes of the tangents to their circular arcs (as geometry/turn_enclosure.hpp encloses
// a turn on the spot), the arc cut into pieces of at most 45 degrees. An enclosure that misses
// every obstacle (exact predicates: CGAL's) and lies inside the bounds proves the motion free. An
// arc whose enclosure hits is cut in halves, down to 1/1024 of 45 degrees; one whose body hits at
// a piece's middle, or that still hits then, is refused: near contact, a motion is never accepted.
//
// Poses are doubles (car/car_pose.hpp), so each enclosure point is computed in floating point and
// grown by a margin that covers its rounding error many times over (car_collision.cpp has the
// error analysis): the proof holds for the exact motion from the double pose, and for the exact
// rational start of a query that the double rounds. Clearance below the margin (about 1e-12 of
// the coordinates' magnitude) is refused as contact.
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/world.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace polyplan {

class CarCollision {
 public:
  // The world's body, obstacles and bounds; its robot must be a car (std::invalid_argument).
  explicit CarCollision(const World& world);
  ~CarCollision();
  CarCollision(CarCollision&&) noexcept;
  CarCollision& operator=(CarCollision&&) noexcept;

  double turning_radius() const;
  bool reverse() const;
  // Whether the reference point lies in the body (closed): then it never enters an obstacle, and
  // the shortest path of a point among the obstacles bounds the car's path length from below.
  bool body_holds_reference_point() const;

  // The body at `pose` misses every obstacle by more than the margin and lies inside the bounds.
  bool pose_is_free(const CarPose& pose) const;
  // What the body at `pose` hits: an obstacle's name ("obstacles[2]"), or "the bounds" when it
  // leaves them; nullopt when the pose is free.
  std::optional<std::string> pose_blocked_by(const CarPose& pose) const;
  // Every pose along `segment` driven from `start` is free: proved by enclosures; false when it
  // collides or comes too near to prove.
  bool segment_is_free(const CarPose& start, const SteeringSegment& segment) const;

  // Whether the body, moved from `end` (the pose a segment driven from `start` ends at, as computed)
  // to `to` (where a path puts its last state: the query's goal), stays within what that segment's
  // certificate encloses: its points move by at most 2^-43 of the segment's scale, well inside the
  // margin's room beyond the rounding (car_collision.cpp). A path that arrives farther off is not
  // certified.
  bool arrival_is_covered(const CarPose& start, const SteeringSegment& segment, const CarPose& end,
                          const CarPose& to) const;

  // Enclosures tested so far (each convex piece's hull counts once): the work certification did.
  std::size_t enclosures_tested() const;

  // The words of a certificate by these enclosures.
  static constexpr const char* method = "swept-body enclosures (hulls of exact arcs' tangent apexes, exact predicates)";

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
