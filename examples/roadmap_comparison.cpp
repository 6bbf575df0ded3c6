// The classical roadmaps side by side on the shipped worlds: the visibility graph (shortest
// paths, grazing the obstacles), the trapezoidal decomposition with the course's zig-zag and with
// the channel's shortest path, the Voronoi maximum-clearance roadmap and the brushfire GVD on a
// grid. For each world's first query: path length, ratio to the optimum, clearance (the path's
// smallest distance to the C-obstacles and walls, geometry/clearance.hpp), build and query time,
// roadmap nodes and edges; and one picture per world and roadmap. A roadmap that is not registered (yet) is listed as
// such. Usage: roadmap_comparison [WORLD.json ...] [--out DIR]   (default: every world of data/worlds)
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/geometry/clearance.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <algorithm>
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
namespace fs = std::filesystem;

// A roadmap as the table names it: a registered planner and its options.
struct Contender {
  std::string label;
  std::string planner;
  OptionValues options;
};

const std::vector<Contender> contenders{
    {"visibility", "visibility", {}},
    {"trapezoid zigzag", "trapezoid", {{"path", "zigzag"}}},
    {"trapezoid funnel", "trapezoid", {{"path", "funnel"}}},
    {"voronoi", "voronoi", {}},
    {"gvd-grid", "gvd-grid", {}},
};

std::string number_or_dash(const Facts& facts, FactKey<double> key, const char* format) {
  const auto value = facts.find(key);
  if (!value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, *value);
  return text;
}

std::string file_name(std::string label) {
  std::replace(label.begin(), label.end(), ' ', '_');
  return label;
}

void compare_on(const std::string& world_file, const fs::path& out) {
  const World world = read_world(world_file);
  if (world.queries.empty()) throw InputError(world_file + ": world: no start/goal and no queries to plan");
  const CSpace cspace(world);
  const Query& query = world.queries.front();
  const std::string world_name = fs::path(world_file).stem().string();
  std::printf("\n%s, %s:\n%-17s %-5s %9s %7s %9s %9s %9s %8s %8s\n", world_name.c_str(), query.name.c_str(), "roadmap",
              "found", "length", "ratio", "clearance", "build s", "query s", "nodes", "edges");
  std::optional<double> optimum;
  for (const Contender& contender : contenders) {
    const PlannerEntry<TranslatingRobot>* entry = planners<TranslatingRobot>().find(contender.planner);
    if (!entry) {
      std::printf("%-17s not registered\n", contender.label.c_str());
      continue;
    }
    std::unique_ptr<Planner<TranslatingRobot>> planner;
    try {
      planner = entry->make(cspace, contender.options);
    } catch (const InputError& e) {  // e.g. a grid needs bounds
      std::printf("%-17s %s\n", contender.label.c_str(), e.what());
      continue;
    }
    const PlanReport<ExactPoint> report = planner->plan(query, QueryOptions{true});
    if (!optimum && report.found && contender.planner == "visibility") optimum = report.length;
    const fs::path picture = out / (world_name + "_" + file_name(contender.label) + ".svg");
    draw_plan(cspace, {report}, {contender.label + " path"}).write(picture.string());
    if (!report.found) {
      std::printf("%-17s %-5s %s\n", contender.label.c_str(), "no", report.why_not.c_str());
      continue;
    }
    std::printf("%-17s %-5s %9.3f %7.4f %9.3f %9s %9s %8lld %8lld\n", contender.label.c_str(), "yes", report.length,
                optimum ? report.length / *optimum : 0.0, path_clearance(cspace, report.path),
                number_or_dash(report.facts, RoadmapFacts::seconds, "%.4f").c_str(),
                number_or_dash(report.facts, QueryFacts::seconds, "%.4f").c_str(),
                static_cast<long long>(report.facts.at(RoadmapFacts::vertices)),
                static_cast<long long>(report.facts.at(RoadmapFacts::edges)));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> worlds;
  fs::path out = ".";
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--out" && i + 1 < argc) out = argv[++i];
    else if (argument.rfind("--", 0) == 0) {
      std::cerr << "usage: roadmap_comparison [WORLD.json ...] [--out DIR]\n";
      return 2;
    } else worlds.push_back(argument);
  }
  if (worlds.empty()) {
    for (const auto& file : fs::directory_iterator(POLYPLAN_DATA_DIR "/worlds"))
      if (file.path().extension() == ".json") worlds.push_back(file.path().string());
    std::sort(worlds.begin(), worlds.end());
  }
  try {
    fs::create_directories(out);
    for (const std::string& world : worlds) compare_on(world, out);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
