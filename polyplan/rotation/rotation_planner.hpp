#pragma once
// Paths for a polygon robot that translates and turns, over a discretized-rotation C-space
// (rotation/rotation_layers.hpp): each layer is the exact C-space of one orientation, and the
// robot may turn from one layer to the next only where the turn layer between them is free, so
// every turn it makes is certified for every intermediate angle; nothing is sampled.
//
// The roadmap's vertices are (layer, position): in each layer the convex corners of its free
// space, the corners of the free space of the turn layers on either side (where turns happen),
// and a query's start and goal. Within a layer, vertices that see each other are joined by
// translations (exact visibility in the layer's triangulated free space); a turn joins a turn
// layer's corner in its two layers. Cost: translation length + weight · |rotation in radians|.
// The search is BGL A* on (layer, vertex) with the admissible heuristic Euclidean distance +
// weight · the smallest rotation still needed. Registered as `rotation`.
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/rotation/rotation_layers.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

struct RotationOptions {
  OrientationOptions orientations;
  // Cost of turning, per radian. Negative: the robot's radius (the largest distance of a robot
  // vertex from its reference point), so a turn costs the arc its farthest point travels.
  double weight = -1;
  SearchOptions search;
};

class RotationPlanner final : public Planner<RotatingRobot> {
 public:
  // Builds the layers, the turn layers and the roadmap. `world` is copied. Throws
  // std::invalid_argument for orientation options it refuses (OrientationSet).
  explicit RotationPlanner(const World& world, RotationOptions options = {});
  ~RotationPlanner() override;
  RotationPlanner(RotationPlanner&&) noexcept;
  RotationPlanner& operator=(RotationPlanner&&) noexcept;

  const RotationLayers& layers() const;
  double rotation_weight() const;  // the weight in use (the robot's radius by default)

  // Facts: rotation (degrees turned in all), translation_length, rotation_weight, layers.count,
  // layers.step, layers.used (distinct layers on the path), layers.actual (each of those layers'
  // nominal angle and its exact rotation's actual one: "60° is 60.0000000017°, ..."),
  // layers.max_error_radians (the largest distance of a layer's exact rotation from its nominal
  // angle), turn_layers.built,
  // turn_layers.used, roadmap.kind ("rotation-layers"), roadmap.vertices, roadmap.edges,
  // roadmap.seconds, search.*, query_seconds. The path's poses carry each layer's exact rotation
  // and its nominal angle, unwrapped along the path: the first is the start's theta as the query
  // gives it, and consecutive angles differ by the turn between them, the short way. Not thread-safe: queries reuse the
  // query slots.
  PlanReport<Pose> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The registry's `rotation`: options rotation-step (5), rotation-count (0: from the step),
// rotation-from (0), rotation-to (360), rotation-weight (radius), search, weight.
PlannerEntry<RotatingRobot> rotation_planner_entry();

}  // namespace polyplan
