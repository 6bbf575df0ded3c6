// Every registered planner of polygon worlds on one world: a table (found, length against the
// exact shortest path, what each searched) and a picture per planner, all from the registry — the
// program names no planner, so a planner added to the registry appears here by itself.
// Usage: planner_gallery [WORLD.json] [OUT_DIR]   (defaults: data/worlds/maze.json and .)
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/registry/registry.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

namespace {

using namespace polyplan;

// A count the report may have, for the table ("-" when the planner does not report it).
std::string count_or_dash(const Facts& facts, FactKey<std::int64_t> key) {
  const auto value = facts.find(key);
  return value ? std::to_string(*value) : "-";
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc > 3) {
    std::cerr << "usage: planner_gallery [WORLD.json] [OUT_DIR]\n";
    return 2;
  }
  const std::string world_file = argc > 1 ? argv[1] : POLYPLAN_DATA_DIR "/worlds/maze.json";
  const fs::path out = argc > 2 ? fs::path(argv[2]) : fs::path(".");
  try {
    const World world = read_world(world_file);
    if (world.queries.empty()) throw InputError(world_file + ": world: no start/goal and no queries to plan");
    const CSpace cspace(world);
    cspace.require_free_queries();
    fs::create_directories(out);
    const Query& query = world.queries.front();
    std::printf("%s, %s:\n\n%-16s %-6s %10s %8s %10s %10s %10s\n", world_file.c_str(), query.name.c_str(), "planner",
                "found", "length", "ratio", "expanded", "vertices", "seconds");
    std::optional<double> shortest;
    for (const PlannerEntry<TranslatingRobot>& entry : planners<TranslatingRobot>().entries()) {
      const Stopwatch planning;
      const auto planner = entry.make(cspace, {});
      const PlanReport<ExactPoint> report = planner->plan(query, QueryOptions{true});
      const double seconds = planning.seconds();
      if (!shortest && report.found) shortest = report.length;  // the first planner, visibility, is exact
      const fs::path picture = out / (entry.name + ".svg");
      draw_plan(cspace, {report}, {entry.name + " path"}).write(picture.string());
      if (report.found)
        std::printf("%-16s %-6s %10.4f %8.4f %10s %10s %10.4f  -> %s\n", entry.name.c_str(), "yes", report.length,
                    report.length / *shortest, count_or_dash(report.facts, SearchFacts::expanded).c_str(),
                    count_or_dash(report.facts, RoadmapFacts::vertices).c_str(), seconds, picture.string().c_str());
      else std::printf("%-16s %-6s %s\n", entry.name.c_str(), "no", report.why_not.c_str());
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
