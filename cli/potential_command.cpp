// polyplan potential WORLD [--zeta Z] [--d-star D] [--eta E] [--q-star Q] [--box XMIN,YMIN,XMAX,YMAX]
// [--cells N] [--json FILE|-] [--svg OUT.svg]: the critical points of the potential-field
// planner's potential for the world's goal (its start/goal), classified by the Hessian, and its
// picture — heat map, contour lines, descent arrows, critical points.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"

#include <polyplan/draw/potential_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/registry/potential_json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace polyplan::cli {
namespace {

struct PotentialOptions {
  std::string world;
  std::string box;
  std::string json, svg;
  std::unique_ptr<CommandOptions<PotentialStudyOptions>> study;  // --zeta, --d-star, --eta, --q-star, --cells
};

// "XMIN,YMIN,XMAX,YMAX".
BoxGrid box_option(const std::string& text, std::size_t cells) {
  const std::vector<double> v = comma_numbers(text, "--box");
  if (v.size() != 4) throw InputError("--box " + text + ": expected XMIN,YMIN,XMAX,YMAX");
  return BoxGrid{v[0], v[1], v[2], v[3], cells};
}

std::string text(Vec2 p) {
  char out[64];
  std::snprintf(out, sizeof out, "(%.6f, %.6f)", p.x, p.y);
  return out;
}

int run_potential(const PotentialOptions& o) {
  std::vector<std::string> warnings;
  const World world = read_world(o.world, &warnings);
  print_warnings(warnings);
  const Vec2 goal = potential_goal(world);
  const PotentialStudyOptions options = o.study->parse();
  const CSpace cspace(world);
  const ObstacleField field(cspace);
  const std::optional<BoxGrid> box = o.box.empty() ? std::nullopt : std::optional(box_option(o.box, options.cells));
  const PotentialStudy study = study_potential(cspace, field, goal, options, box, "--box " + o.box);
  if (!o.json.empty()) write_json(potential_json(study), o.json);
  if (!o.svg.empty()) draw_potential_study(cspace, field, study).write(o.svg);
  if (o.json != "-") {
    const BoxGrid& b = study.box;
    std::cout << study.found.points.size() << " critical point(s) in the free space of [" << b.xmin << ", " << b.xmax
              << "] x [" << b.ymin << ", " << b.ymax << "] (" << study.found.candidates << " candidate cells of "
              << b.cells_per_axis << " x " << b.cells_per_axis << ")\n";
    for (const CriticalPoint& p : study.found.points)
      std::cout << "  " << p.kind << " at " << text(p.at) << ", U = " << p.value << '\n';
    if (!o.svg.empty()) std::cout << "picture: " << o.svg << '\n';
  }
  return ok;
}

}  // namespace

void add_potential_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<PotentialOptions>();
  CLI::App* command = app.add_subcommand(
      "potential", "The critical points of the potential-field planner's potential, and its picture");
  command->add_option("world", options->world, "world file (JSON); its start/goal gives the goal")->required();
  options->study = std::make_unique<CommandOptions<PotentialStudyOptions>>(*command, potential_study_options());
  command->add_option("--box", options->box,
                      "the box to search, XMIN,YMIN,XMAX,YMAX (default: the bounds, or the box around the world)");
  command->add_option("--json", options->json,
                      "write the critical points as JSON to this file ('-' for standard output)");
  command->add_option("--svg", options->svg,
                      "draw the potential, its contours, the descent arrows and the critical points");
  command->callback([options, &run] { run = [options] { return run_potential(*options); }; });
}

}  // namespace polyplan::cli
