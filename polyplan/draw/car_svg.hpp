#pragma once
// Pictures of a steered car's plans, drawn from the reports alone (any planner of SteeredCar):
// the world, the search tree or graph (each edge the segment the car drove, thin), the car's body
// along each path as a strobe — forward and reverse in two colours, the body at start and goal
// bold — the reference point's track, and the start and goal poses as arrows.
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <string>
#include <vector>

namespace polyplan {

// `labels[i]` names report i's path (default "path", or "path i" for several). The world's robot
// must be a car (its turning radius shapes the drawn arcs).
svg::Drawing draw_plan(const World& world, const std::vector<PlanReport<CarState>>& reports,
                       const std::vector<std::string>& labels = {});

}  // namespace polyplan
