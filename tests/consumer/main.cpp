// Reads a world and plans it with the registry's default planner, and plans a two-link arm with
// the arm registry's grid planner: proof that the installed headers and libraries (with their
// public Eigen, Boost and nlohmann-json dependencies) are usable on their own.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>

#include <nlohmann/json.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const polyplan::World world = polyplan::read_world(argv[1]);
  const polyplan::CSpace cspace(world);
  std::cout << "free components: " << cspace.free_components().size() << '\n';
  const auto planner = polyplan::planners<polyplan::TranslatingRobot>().find("visibility")->make(cspace, {});
  const auto plan = planner->plan(world.queries.front());
  std::cout << "plan: " << polyplan::plan_json(plan, world.queries.front().name).dump() << '\n';

  polyplan::ArmProblem arm;
  arm.arm.links = {1.0, 1.0};
  arm.points = {{1.5, 0.2}};
  const auto arm_planner = polyplan::planners<polyplan::PlanarArm>().find("grid")->make(arm, {{"resolution", "10"}});
  const auto arm_plan = arm_planner->plan({"consumer", {0.5, 0.0}, {-0.5, 0.0}});
  std::cout << "arm: " << (arm_plan.found ? "found" : "no path") << ", length " << arm_plan.length << '\n';
  return cspace.free_components().empty() || !plan.found || !arm_plan.found ? 1 : 0;
}
