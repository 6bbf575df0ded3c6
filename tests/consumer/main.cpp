// Reads a world and prints the number of free components, and plans a two-link arm on its C-space
// grid: proof that the installed headers and libraries (with their public Eigen and Boost
// dependencies) are usable on their own.
#include <polyplan/arm/arm_grid_planner.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const polyplan::CSpace cspace(polyplan::read_world(argv[1]));
  std::cout << "free components: " << cspace.free_components().size() << '\n';
  polyplan::ArmProblem arm;
  arm.arm.links = {1.0, 1.0};
  arm.points = {{1.5, 0.2}};
  const polyplan::ArmQuery query{"consumer", {0.5, 0.0}, {-0.5, 0.0}};
  const auto plan = polyplan::plan_arm_on_grid(arm, query, {});
  std::cout << "arm: " << (plan.found ? "found" : "no path") << ", length " << plan.length << '\n';
  return cspace.free_components().empty() || !plan.found ? 1 : 0;
}
