#pragma once
// What `polyplan potential` and Python's polyplan.potential compute alike: their options, declared
// once with the potential-field planner's weights (so the same names, ranges and messages), the box
// searched, the critical points found. Its JSON: registry/potential_json.hpp.
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/reactive/critical_points.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace polyplan {

// The potential's weights and distances as the potential-field planner and a study take them:
// "zeta", "d-star", "eta" and "q-star" of any options with those members.
template <class Options>
OptionTable<Options>& add_potential_weights(OptionTable<Options>& table) {
  return table.add("zeta", &Options::zeta, "weight of the goal's attraction", above(0))
      .add("d-star", &Options::d_star,
           "quadratic attraction within this distance of the goal, conic beyond (0: conic everywhere)", at_least(0))
      .add("eta", &Options::eta, "weight of each obstacle's repulsion", at_least(0))
      .add("q-star", &Options::q_star, "an obstacle farther than this does not repel", at_least(0));
}

// What a study of the potential takes: the weights, and the cells per side of the box searched.
struct PotentialStudyOptions {
  double zeta = 1, d_star = 0, eta = 1, q_star = 1;
  std::size_t cells = 256;
  PotentialParameters parameters() const { return {{zeta, d_star}, {eta, q_star}}; }
};
const OptionTable<PotentialStudyOptions>& potential_study_options();

struct PotentialStudy {
  Vec2 goal;
  PotentialParameters parameters;
  BoxGrid box;
  CriticalPoints found;
};

// The goal of the world's first query. Throws InputError naming the world file when it has none.
Vec2 potential_goal(const World& world);

// The critical points in `box` (none: the world's bounds, or the box around it) cut into
// options.cells × options.cells. Throws InputError for an empty box, naming `box_name`.
PotentialStudy study_potential(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                               const PotentialStudyOptions& options, const std::optional<BoxGrid>& box,
                               const std::string& box_name);

}  // namespace polyplan
