#pragma once
// The C-space of a world with round things and thin walls (World::round_features): where the
// robot's reference point may not be, as cores grown by radii. Every C-obstacle of a point, disc
// or translating polygon robot among discs, walls and polygons is one of these, all rational:
//
//   robot          disc (c, ρ)                 wall (polyline)                 polygon O
//   point          point c, radius ρ           wall, radius 0 (never crossed)  polygon O, radius 0
//   disc r         point c, radius ρ + r       wall, radius r                  polygon O, radius r
//   polygon R      polygon c − R, radius ρ     polygon W ⊕ (−R), radius 0      polygon O ⊕ (−R), radius 0
//
// A core grown by a radius is the set of points within that distance of it (the polygon's inside
// included): a rounded polygon, a chain of stadiums, a disc. A wall of radius 0 blocks no point, only
// crossings: a motion may touch and slide along it. For a polygon robot the Minkowski sums of the
// polygons and of the walls (a wall's segment ⊕ (−R) is −R at its two ends and the parallelograms
// it sweeps with −R's edges) are joined into solids, so that C-obstacles meeting along an edge are
// one, as the polygon world's C-space joins them; a disc's cores, one per part of the robot, are
// grown by ρ > 0 and overlap wherever they touch.
#include <polyplan/geometry/world.hpp>

#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct RoundCore {
  enum class Kind { point, wall, polygon };
  Kind kind = Kind::point;
  // point: its centre; wall: the polyline; polygon: none.
  std::vector<ExactPoint> points;
  std::vector<Ring> rings;  // polygon: its outer ring (counter-clockwise), then its holes (clockwise)
  Rational radius;          // ≥ 0; 0 only for a polygon or a wall
  std::string name;         // "discs[2]", "walls[0]", "obstacles[1]", for messages
};

struct RoundCSpace {
  std::vector<RoundCore> obstacles;
  // Where the reference point keeps to: the box bounds shrunk so that the robot stays inside
  // (empty, xmin > xmax, when it does not fit), or the disc bounds shrunk by a disc robot's radius
  // (a radius < 0 when it does not fit). None without bounds.
  std::optional<Bounds> box;
  std::optional<Disc> disc;
  enum class Robot { point, disc, polygon };
  Robot robot = Robot::point;
};

// Whether every C-obstacle is straight-edged (each core of radius 0: polygons and walls) and the
// bounds are no disc: the free space's boundary then has no arc.
bool straight_edged(const RoundCSpace& space);

// The world's C-space. Throws InputError naming the world's file for a polygon robot in disc
// bounds (where it fits is an intersection of discs, not a core grown by a radius).
RoundCSpace round_cspace(const World& world);

}  // namespace polyplan
