#pragma once
// The checks made before a planner of the registry answers a world's own queries (`polyplan plan
// WORLD.json`, Python's polyplan.plan(world)): the world has a query, and every start and goal is
// a free configuration of the planner's space. A query asked on its own (Planner::plan) needs
// none of this: a start that is not free is an answer there (status invalid_query).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/world.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

// InputError naming the world's file and the query when the world has no query, or a start or
// goal is not free: for `planner` (a name of planners<TranslatingRobot>(), planners<RotatingRobot>()
// or planners<SteeredCar>(): a car's body at its poses) at the query's orientation; a translating planner also refuses
// an orientation other than 0 degrees. `cspace` is the world's C-space, which a translating planner's check reads (a
// rotating planner's builds those of its orientations: null will do).
void require_plannable_queries(const World& world, const CSpace* cspace, std::string_view planner);

// InputError when `planner` cannot plan for the world's robot at all, asked or not: a car's
// (robot.car) paths must keep to its turning radius, which no translating or rotating planner does,
// and a car planner needs the car's turning radius; a world with "changes" goes only to a planner
// that follows them (PlannerEntry::follows_world_changes), and one with discs, walls, disc bounds
// or a disc robot (round_features) only to a planner that plans with them
// (PlannerEntry::plans_round_worlds), the refusal naming what the world has.
void require_planner_for_robot(const World& world, std::string_view planner);

// The planners that follow a world's "changes" (of polygon worlds; those of round worlds have the
// same names), in the registry's order (the first is a changing world's default).
std::vector<std::string> planners_following_changes();

// A world's default planner in a space whose own default is `still`: for a world that changes, the
// first planner that follows the changes, or `still` when none is built (which then refuses the
// world, naming the change).
std::string default_planner_for_changes(const World& world, std::string still);

// The planners of every space that plan with discs, walls, disc bounds and a disc robot.
std::vector<std::string> planners_for_round_worlds();

}  // namespace polyplan
