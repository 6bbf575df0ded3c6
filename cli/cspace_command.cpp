// polyplan cspace WORLD.json [--svg OUT.svg] [--json -]: builds the exact C-space and reports it.
#include "cli/command.hpp"

#include <polyplan/draw/round_cspace_svg.hpp>
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/round_cspace_area.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace polyplan::cli {
namespace {

struct CSpaceOptions {
  std::string world;
  std::string svg;
  std::string json;
};

nlohmann::json summary(const CSpace& cspace, double seconds) {
  nlohmann::json components = nlohmann::json::array();
  for (const FreeComponent& c : cspace.free_components()) {
    nlohmann::json item{{"unbounded", !c.area.has_value()}, {"holes", c.holes.size()}};
    item["area"] = c.area ? nlohmann::json(to_string(*c.area)) : nlohmann::json(nullptr);
    item["area_double"] = c.area ? nlohmann::json(to_double(*c.area)) : nlohmann::json(nullptr);
    components.push_back(item);
  }
  const World& world = cspace.world();
  return {{"world", world.source},
          {"robot", world.robot.is_point() ? "point" : std::to_string(world.robot.parts.size()) + " part(s)"},
          {"obstacles", world.obstacles.size()},
          {"solids", cspace.solids().size()},
          {"cobstacles", cspace.cobstacles().size()},
          {"free_components", components},
          {"seconds", seconds}};
}

void print_table(const nlohmann::json& s) {
  std::cout << s["world"].get<std::string>() << ": robot " << s["robot"].get<std::string>() << ", " << s["obstacles"]
            << " obstacle(s) joined into " << s["solids"] << " solid(s), " << s["cobstacles"] << " C-obstacle(s), "
            << s["free_components"].size() << " free component(s)\n";
  std::size_t i = 0;
  for (const auto& c : s["free_components"]) {
    std::cout << "  free component " << i++ << ": ";
    if (c["unbounded"].get<bool>()) std::cout << "unbounded";
    else std::cout << "area " << c["area"].get<std::string>() << " (" << c["area_double"].get<double>() << ")";
    std::cout << ", " << c["holes"] << " hole(s)\n";
  }
  std::printf("  built in %.3f s\n", s["seconds"].get<double>());
}

std::string robot_text(const World& world) {
  if (world.robot.disc) return "disc r " + to_string(*world.robot.disc);
  if (world.robot.is_point()) return "point";
  return "polygon, " + std::to_string(world.robot.parts.size()) + " part(s)";
}

// A round world's summary: the robot, its C-obstacles by kind (cores grown by radii), the free area.
nlohmann::json round_summary(const RoundWorld& round, const FreeArea& area, double seconds) {
  const World& world = round.world();
  std::size_t discs = 0, walls = 0, polygons = 0, rounded = 0;
  for (const RoundCore& core : round.cspace().obstacles) {
    discs += core.kind == RoundCore::Kind::point;
    walls += core.kind == RoundCore::Kind::wall;
    polygons += core.kind == RoundCore::Kind::polygon;
    rounded += core.kind == RoundCore::Kind::polygon && core.radius > 0;
  }
  nlohmann::json s{{"world", world.source},
                   {"robot", robot_text(world)},
                   {"cobstacles", {{"discs", discs}, {"walls", walls}, {"polygons", polygons}, {"rounded", rounded}}},
                   {"bounded", area.bounded},
                   {"exact", area.exact.has_value()},
                   {"area_text", free_area_text(area)},
                   {"seconds", seconds}};
  if (area.exact) {
    s["area"] = to_string(*area.exact);
    s["area_double"] = to_double(*area.exact);
  }
  if (area.bounded) {
    s["area_lower"] = area.lower;
    s["area_upper"] = area.upper;
  }
  return s;
}

void print_round_table(const nlohmann::json& s) {
  const nlohmann::json& c = s["cobstacles"];
  std::cout << s["world"].get<std::string>() << ": robot " << s["robot"].get<std::string>()
            << ", C-obstacles: " << c["discs"] << " disc(s), " << c["walls"] << " wall(s), " << c["polygons"]
            << " polygon(s) (" << c["rounded"] << " rounded)\n";
  std::cout << "  free area " << s["area_text"].get<std::string>() << '\n';
  std::printf("  built in %.3f s\n", s["seconds"].get<double>());
}

// A world with discs or walls: its C-space as cores grown by radii (geometry/round_cspace.hpp).
int run_round_cspace(const World& world, const CSpaceOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const RoundWorld round(world);
  for (const Query& q : world.queries)  // refused as the round planners' door refuses them
    for (const auto& [what, point] : {std::pair{".start", &q.start}, std::pair{".goal", &q.goal}})
      if (auto why = round.config_not_free(*point)) throw InputError(world.source + ": " + q.name + what + ": " + *why);
  const FreeArea area = round_free_area(round.cspace(), world.source);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!options.svg.empty()) round_cspace_picture(world, round.cspace()).write(options.svg);
  const nlohmann::json s = round_summary(round, area, seconds);
  if (!options.json.empty()) write_json(s, options.json);
  if (options.json != "-") print_round_table(s);
  if (!options.svg.empty() && options.json != "-") std::cout << "  picture: " << options.svg << '\n';
  return ok;
}

int run_cspace(const CSpaceOptions& options) {
  std::vector<std::string> warnings;
  const World world = read_world(options.world, &warnings);
  print_warnings(warnings);
  if (!round_features(world).empty()) return run_round_cspace(world, options);
  const auto started = std::chrono::steady_clock::now();
  CSpace cspace(world);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  cspace.require_free_queries();
  if (!options.svg.empty()) write_cspace_svg(cspace, options.svg);
  const nlohmann::json s = summary(cspace, seconds);
  if (!options.json.empty()) write_json(s, options.json);
  if (options.json != "-") print_table(s);
  if (!options.svg.empty() && options.json != "-") std::cout << "  picture: " << options.svg << '\n';
  return ok;
}

}  // namespace

void add_cspace_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<CSpaceOptions>();
  CLI::App* command = app.add_subcommand("cspace", "Build the exact configuration space of a world and summarise it");
  command->add_option("world", options->world, "World file (JSON)")->required();
  command->add_option("--svg", options->svg, "Write a picture of the world and its C-space");
  command->add_option("--json", options->json, "Write the summary as JSON to this file ('-' for standard output)");
  command->callback([options, &run] { run = [options] { return run_cspace(*options); }; });
}

}  // namespace polyplan::cli
