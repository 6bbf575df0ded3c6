#pragma once
// Pictures of a rotating robot's plans, drawn from the reports alone (any planner of
// RotatingRobot): the world, the robot drawn along each path as a strobe whose colour runs from
// start to goal (turns show as fans of the robot on one spot), the reference point's track with the
// turning places marked, and beside the world a panel of the orientation along each path.
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <string>
#include <vector>

namespace polyplan {

// `labels[i]` names report i's path (default "path", or "path i" for several). A report without
// a path draws nothing but the world's starts and goals.
svg::Drawing draw_plan(const World& world, const std::vector<PlanReport<Pose>>& reports,
                       const std::vector<std::string>& labels = {});

}  // namespace polyplan
