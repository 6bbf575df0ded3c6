// The course's C-space and visibility-graph problem set's Part 2 with certified turns: a rotating robot planned over
// layers of orientations at several steps, against the same robot that may not turn. A table on stdout (layers, turn
// layers, found, length, degrees turned, motions, build and query times) and a strobe picture per
// step.
// Usage: rotation_steps [WORLD.json] [OUT_PREFIX] [STEP...]
//   defaults: data/worlds/rotation_seed004.json, "rotation", 10 5 2 → rotation_10.svg, ...
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/rotation/rotation_facts.hpp>
#include <polyplan/rotation/rotation_planner.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

using namespace polyplan;

int main(int argc, char** argv) {
  const std::string world_file = argc > 1 ? argv[1] : POLYPLAN_DATA_DIR "/worlds/rotation_seed004.json";
  const std::string prefix = argc > 2 ? argv[2] : "rotation";
  std::vector<double> steps{10, 5, 2};
  if (argc > 3) {
    steps.clear();
    for (int i = 3; i < argc; ++i) {
      try {
        steps.push_back(std::stod(argv[i]));
      } catch (const std::exception&) {
        std::cerr << "rotation_steps: not a number of degrees: " << argv[i] << '\n';
        return 2;
      }
    }
  }

  try {
    const World world = read_world(world_file);
    if (world.queries.empty()) throw InputError(world_file + ": world: no start/goal to plan");
    const Query& query = world.queries.front();

    RotationOptions fixed;
    fixed.orientations.count = 1;
    const PlanReport<Pose> without = RotationPlanner(world, fixed).plan(query);
    std::printf("without turning: %s\n", without.found ? "path" : ("no path (" + without.why_not + ")").c_str());

    std::printf("%6s %7s %11s %6s %10s %9s %8s %9s %9s\n", "step", "layers", "turn layers", "found", "length", "turned",
                "motions", "build s", "query ms");
    for (double step : steps) {
      RotationOptions options;
      options.orientations.step = step;
      const Stopwatch building;
      RotationPlanner planner(world, options);
      const double build_seconds = building.seconds();
      const PlanReport<Pose> report = planner.plan(query);
      std::printf("%5g° %7zu %11zu %6s %10.3f %8.1f° %8zu %9.2f %9.2f\n", step, planner.layers().layers().size(),
                  planner.layers().turns().size(), report.found ? "yes" : "no", report.found ? report.length : 0.0,
                  report.facts.at(RotationFacts::rotation), report.path.empty() ? 0 : report.path.size() - 1,
                  build_seconds, report.facts.at(QueryFacts::seconds) * 1000);
      char name[64];
      std::snprintf(name, sizeof name, "_%g.svg", step);
      draw_plan(world, {report}, {"path, every " + std::to_string(static_cast<int>(step)) + "°"}).write(prefix + name);
    }
  } catch (const std::exception& e) {
    std::cerr << "rotation_steps: " << e.what() << '\n';
    return 2;
  }
}
