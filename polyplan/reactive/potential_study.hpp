#pragma once
// What `polyplan potential` and Python's polyplan.potential compute alike: the inputs checked
// (messages naming each input as the caller's users spell it: "--eta" or "eta"), the box searched,
// the critical points found. Its JSON: registry/potential_json.hpp.
#include <polyplan/reactive/critical_points.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace polyplan {

struct PotentialNames {
  std::string zeta, d_star, eta, q_star, cells;
};

struct PotentialStudy {
  Vec2 goal;
  PotentialParameters parameters;
  BoxGrid box;
  CriticalPoints found;
};

// The goal of the world's first query. Throws InputError naming the world file when it has none.
Vec2 potential_goal(const World& world);

// Throws InputError for a weight or distance that is negative or not finite, or cells not in
// 1 … 4096, naming it as `names` says.
void check_potential_inputs(const PotentialParameters& parameters, std::size_t cells, const PotentialNames& names);

// The critical points in `box` (none: the world's bounds, or the box around it) cut into
// cells × cells. Throws InputError for an empty box, naming `box_name`.
PotentialStudy study_potential(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                               const PotentialParameters& parameters, const std::optional<BoxGrid>& box,
                               std::size_t cells, const std::string& box_name);

}  // namespace polyplan
