// polyplan cspace WORLD.json [--svg OUT.svg] [--json -]: builds the exact C-space and reports it.
#include "cli/command.hpp"

#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
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

int run_cspace(const CSpaceOptions& options) {
  std::vector<std::string> warnings;
  const World world = read_world(options.world, &warnings);
  print_warnings(warnings);
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
