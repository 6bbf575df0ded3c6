#include <polyplan/reactive/potential_study.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/planner_options.hpp>

namespace polyplan {

Vec2 potential_goal(const World& world) {
  if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal: the potential needs the goal");
  return approximate(world.queries.front().goal);
}

const OptionTable<PotentialStudyOptions>& potential_study_options() {
  static const OptionTable<PotentialStudyOptions> table = [] {
    OptionTable<PotentialStudyOptions> t;
    add_potential_weights(t).add("cells", &PotentialStudyOptions::cells, "cells per side of the box searched",
                                 in_range(1, 4096));
    return t;
  }();
  return table;
}

PotentialStudy study_potential(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                               const PotentialStudyOptions& options, const std::optional<BoxGrid>& box,
                               const std::string& box_name) {
  const PotentialParameters parameters = options.parameters();
  PotentialStudy study{goal, parameters, box ? *box : box_around(cspace, options.cells), {}};
  study.box.cells_per_axis = options.cells;
  if (!(study.box.xmax > study.box.xmin) || !(study.box.ymax > study.box.ymin))
    throw InputError(box_name + ": expected XMIN < XMAX and YMIN < YMAX");
  study.found = find_critical_points(cspace, field, goal, parameters, study.box);
  return study;
}

}  // namespace polyplan
