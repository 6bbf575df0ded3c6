#pragma once
// The layered C-space of a rotating robot: a discrete set of orientations, each an exact rational
// rotation whose C-space is exact (a layer), and for each pair of neighbouring orientations the
// exact C-space of the turn between them (a turn layer: the robot replaced by polygons that
// contain everything it sweeps while turning, geometry/turn_enclosure.hpp). A position free in a
// turn layer is a position where the turn is free for every intermediate angle.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/world.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

// Which orientations to use, in degrees: `count` layers, or (count 0) one every `step` degrees,
// over [from, to]. Without `to`, or with to = from + 360, the whole circle: its last layer
// neighbours its first, and from + 360 is `from` again.
struct OrientationOptions {
  double step = 5;
  std::size_t count = 0;
  double from = 0;
  std::optional<double> to;
};

// The largest number of layers (each is a C-space, and so is each turn).
inline constexpr std::size_t max_rotation_layers = 3600;

class OrientationSet {
 public:
  // Throws std::invalid_argument naming the option: a step <= 0 or not dividing the range, a range
  // that is empty, reversed or wider than 360 degrees, neighbours 180 degrees or more apart (a turn
  // layer encloses less than a half turn), more than max_rotation_layers layers.
  explicit OrientationSet(const OrientationOptions& options);

  std::size_t size() const { return degrees_.size(); }
  double degrees(std::size_t layer) const { return degrees_[layer]; }
  double step() const { return step_; }
  bool whole_circle() const { return whole_circle_; }

  // The turns between neighbouring layers, as (layer, next layer): n of them on the whole
  // circle (for n >= 3), n - 1 over a range.
  std::vector<std::pair<std::size_t, std::size_t>> turns() const;

  // The angle as this set writes it: on the whole circle in [from, from + 360); over a range the
  // one of angle + 360 k within [from, to]; nullopt when none is.
  std::optional<double> normalized(double degrees) const;
  // The layer whose angle is exactly `degrees` (normalized first), if any.
  std::optional<std::size_t> layer_at(double degrees) const;
  // The layers nearest to an angle of the set (one, or the two on either side when it lies
  // halfway between them).
  std::vector<std::size_t> nearest(double normalized_degrees) const;
  // How far one must turn from angle a to angle b, both of the set, staying in it (degrees).
  double distance(double a, double b) const;

 private:
  std::vector<double> degrees_;
  double step_ = 0;
  bool whole_circle_ = true;
};

struct RotationLayer {
  double degrees = 0;  // nominal
  Rotation rotation;   // exact, within rotation_tolerance_radians of `degrees`
  World world;         // the world with the robot turned
  std::unique_ptr<CSpace> cspace;
};

struct TurnLayer {
  std::size_t from = 0, to = 0;  // the neighbouring layers it joins
  double turn_degrees = 0;       // from → to, the short way, between the exact rotations
  World world;                   // the world with the robot replaced by its turn enclosure
  std::unique_ptr<CSpace> cspace;
  std::vector<ExactPoint> corners;  // the vertices of its free space's boundary: where turns happen
};

class RotationLayers {
 public:
  // Builds every layer's and every turn layer's exact C-space.
  RotationLayers(const World& world, const OrientationSet& orientations);

  const World& world() const { return world_; }
  const OrientationSet& orientations() const { return orientations_; }
  const std::vector<RotationLayer>& layers() const { return layers_; }
  const std::vector<TurnLayer>& turns() const { return turns_; }

 private:
  World world_;
  OrientationSet orientations_;
  std::vector<RotationLayer> layers_;
  std::vector<TurnLayer> turns_;
};

// The world with `robot` in place of its own (turned, or a turn enclosure).
World world_with_robot(const World& world, Robot robot);

// Throws InputError (naming the world file, the query, the pose with its angle and what the robot
// hits there) when a start or goal pose of the world's queries is not free: `polyplan plan`'s
// check before a rotating robot is planned, as CSpace::require_free_queries is for a translating one.
void require_free_poses(const World& world);

}  // namespace polyplan
