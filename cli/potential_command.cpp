// polyplan potential WORLD [--zeta Z] [--d-star D] [--eta E] [--q-star Q] [--box XMIN,YMIN,XMAX,YMAX]
// [--cells N] [--json FILE|-] [--svg OUT.svg]: the critical points of the potential-field
// planner's potential for the world's goal (its start/goal), classified by the Hessian, and its
// picture — heat map, contour lines, descent arrows, critical points.
#include "cli/command.hpp"

#include <polyplan/draw/potential_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/critical_points.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace polyplan::cli {
namespace {

struct PotentialOptions {
  std::string world;
  double zeta = 1, d_star = 0, eta = 1, q_star = 1;
  std::string box;
  std::size_t cells = 256;
  std::string json, svg;
};

// "XMIN,YMIN,XMAX,YMAX".
BoxGrid box_option(const std::string& text, std::size_t cells) {
  const std::vector<double> v = comma_numbers(text, "--box");
  if (v.size() != 4) throw InputError("--box " + text + ": expected XMIN,YMIN,XMAX,YMAX");
  const BoxGrid box{v[0], v[1], v[2], v[3], cells};
  if (!(box.xmax > box.xmin) || !(box.ymax > box.ymin)) throw InputError("--box " + text + ": expected XMIN < XMAX and YMIN < YMAX");
  return box;
}

std::string text(Vec2 p) {
  char out[64];
  std::snprintf(out, sizeof out, "(%.6f, %.6f)", p.x, p.y);
  return out;
}

nlohmann::json potential_json(const PotentialOptions& o, const BoxGrid& box, Vec2 goal, const CriticalPoints& found) {
  nlohmann::json points = nlohmann::json::array();
  for (const CriticalPoint& p : found.points)
    points.push_back({{"at", {p.at.x, p.at.y}}, {"kind", p.kind}, {"eigenvalues", {p.eigenvalues.smaller, p.eigenvalues.larger}},
                      {"value", p.value}, {"gradient", p.gradient}});
  return {{"goal", {goal.x, goal.y}},
          {"parameters", {{"zeta", o.zeta}, {"d_star", o.d_star}, {"eta", o.eta}, {"q_star", o.q_star}}},
          {"box", {box.xmin, box.ymin, box.xmax, box.ymax}},
          {"cells_per_axis", box.cells_per_axis},
          {"candidates", found.candidates},
          {"critical_points", points}};
}

int run_potential(const PotentialOptions& o) {
  std::vector<std::string> warnings;
  const World world = read_world(o.world, &warnings);
  print_warnings(warnings);
  if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal: the potential needs the goal");
  if (o.cells == 0 || o.cells > 4096) throw InputError("--cells " + std::to_string(o.cells) + ": expected 1 to 4096");
  for (const auto& [value, name] : {std::pair{o.zeta, "--zeta"}, {o.d_star, "--d-star"}, {o.eta, "--eta"}, {o.q_star, "--q-star"}})
    if (!std::isfinite(value) || value < 0) throw InputError(std::string(name) + " " + std::to_string(value) + ": expected a finite number of at least 0");
  const CSpace cspace(world);
  const ObstacleField field(cspace);
  const PotentialParameters parameters{{o.zeta, o.d_star}, {o.eta, o.q_star}};
  const Vec2 goal = approximate(world.queries.front().goal);
  const BoxGrid box = o.box.empty() ? box_around(cspace, o.cells) : box_option(o.box, o.cells);
  const CriticalPoints found = find_critical_points(cspace, field, goal, parameters, box);
  if (!o.json.empty()) write_json(potential_json(o, box, goal, found), o.json);
  if (!o.svg.empty()) {
    BoxGrid picture = box;
    picture.cells_per_axis = std::min<std::size_t>(box.cells_per_axis, 160);
    draw_potential(cspace, potential_map(cspace, field, goal, parameters, picture), field, goal, parameters, found.points).write(o.svg);
  }
  if (o.json != "-") {
    std::cout << found.points.size() << " critical point(s) in the free space of [" << box.xmin << ", " << box.xmax << "] x [" << box.ymin
              << ", " << box.ymax << "] (" << found.candidates << " candidate cells of " << box.cells_per_axis << " x " << box.cells_per_axis
              << ")\n";
    for (const CriticalPoint& p : found.points) std::cout << "  " << p.kind << " at " << text(p.at) << ", U = " << p.value << '\n';
    if (!o.svg.empty()) std::cout << "picture: " << o.svg << '\n';
  }
  return ok;
}

}  // namespace

void add_potential_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<PotentialOptions>();
  CLI::App* command = app.add_subcommand("potential", "The critical points of the potential-field planner's potential, and its picture");
  command->add_option("world", options->world, "world file (JSON); its start/goal gives the goal")->required();
  command->add_option("--zeta", options->zeta, "weight of the goal's attraction")->capture_default_str();
  command->add_option("--d-star", options->d_star, "quadratic attraction within this distance, conic beyond (0: conic everywhere)")
      ->capture_default_str();
  command->add_option("--eta", options->eta, "weight of each obstacle's repulsion")->capture_default_str();
  command->add_option("--q-star", options->q_star, "an obstacle farther than this does not repel")->capture_default_str();
  command->add_option("--box", options->box, "the box to search, XMIN,YMIN,XMAX,YMAX (default: the bounds, or the box around the world)");
  command->add_option("--cells", options->cells, "cells per side of the box's subdivision")->capture_default_str();
  command->add_option("--json", options->json, "write the critical points as JSON to this file ('-' for standard output)");
  command->add_option("--svg", options->svg, "draw the potential, its contours, the descent arrows and the critical points");
  command->callback([options, &run] { run = [options] { return run_potential(*options); }; });
}

}  // namespace polyplan::cli
