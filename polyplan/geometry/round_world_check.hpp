#pragma once
// Exact checks of a point, disc or translating polygon robot's motions in a world with round things and thin walls
// (discs, walls, disc bounds; World::round_features), under docs/design.md's semantics: a motion
// may touch and slide along an obstacle (a path grazing a disc tangentially is valid, one sliding
// along a wall too), it never enters one, never crosses a wall, and never passes through a
// zero-width passage (a point where obstacles touch, or two discs are tangent, or a gap is exactly
// as wide as the robot).
//
// Every C-obstacle is a core grown by a radius (geometry/round_cspace.hpp's table): a disc's centre,
// a wall's piece, a polygon or a polygon robot's Minkowski sum, with the radii the table gives.
// A configuration q is blocked by it when dist(q, core) < radius (a polygon or wall of radius 0:
// q inside the polygon; a wall of radius 0 blocks no configuration, only crossings). All of it in
// rationals: distances are compared squared, and where a motion touches an obstacle it touches it
// at rational points (a tangent point is a projection), where the directions the motion may take
// are decided by signs of dot and cross products (round_world_check.cpp says how).
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/round_cspace.hpp>
#include <polyplan/geometry/world.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

class RoundWorld {
 public:
  // InputError naming the world's file for a world round_cspace refuses.
  explicit RoundWorld(const World& world);
  ~RoundWorld();
  RoundWorld(RoundWorld&&) noexcept;
  RoundWorld& operator=(RoundWorld&&) noexcept;

  // The world it checks, its C-space, and where the robot's reference point may be (the C-space's
  // box or disc).
  const World& world() const;
  const RoundCSpace& cspace() const;
  const std::optional<Bounds>& reference_box() const;
  const std::optional<Disc>& reference_disc() const;

  // Why q is not a free configuration (inside which obstacle, or outside the bounds), or none.
  std::optional<std::string> config_not_free(const ExactPoint& q) const;
  // The polyline as a motion, vertex by vertex and segment by segment.
  PathCheck check_path(const std::vector<ExactPoint>& path) const;
  // The straight motion from a to b, both ends included.
  PathCheck check_segment(const ExactPoint& a, const ExactPoint& b) const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

}  // namespace polyplan
