#include <polyplan/reactive/potential_study.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <cmath>
#include <utility>

namespace polyplan {

Vec2 potential_goal(const World& world) {
  if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal: the potential needs the goal");
  return approximate(world.queries.front().goal);
}

void check_potential_inputs(const PotentialParameters& p, std::size_t cells, const PotentialNames& names) {
  const std::pair<double, const std::string*> inputs[] = {{p.attractive.zeta, &names.zeta},
                                                          {p.attractive.d_star, &names.d_star},
                                                          {p.repulsive.eta, &names.eta},
                                                          {p.repulsive.q_star, &names.q_star}};
  for (const auto& [value, name] : inputs)
    if (!std::isfinite(value) || value < 0)
      throw InputError(*name + " " + detail::show_number(value) + ": expected a finite number of at least 0");
  if (cells == 0 || cells > 4096) throw InputError(names.cells + " " + std::to_string(cells) + ": expected 1 to 4096");
}

PotentialStudy study_potential(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                               const PotentialParameters& parameters, const std::optional<BoxGrid>& box,
                               std::size_t cells, const std::string& box_name) {
  PotentialStudy study{goal, parameters, box ? *box : box_around(cspace, cells), {}};
  study.box.cells_per_axis = cells;
  if (!(study.box.xmax > study.box.xmin) || !(study.box.ymax > study.box.ymin))
    throw InputError(box_name + ": expected XMIN < XMAX and YMIN < YMAX");
  study.found = find_critical_points(cspace, field, goal, parameters, study.box);
  return study;
}

}  // namespace polyplan
