// polyplan check PROBLEM.json PATH.json [--json -]: is this path a valid motion of the problem's
// robot (a polyline; a rotating robot's poses; a car's segments; an arm's joint angles)? Exit 0 when
// it is, 1 when it is not, 2 on bad input.
#include "cli/command.hpp"

#include <polyplan/registry/robot_path_check.hpp>

#include <iostream>

namespace polyplan::cli {
namespace {

struct CheckOptions {
  std::string world;
  std::string path;
  std::string json;
};

int run_check(const CheckOptions& options) {
  std::vector<std::string> warnings;
  const Problem problem = Problem::read(options.world, &warnings);
  print_warnings(warnings);
  const PathCheck result = check_path_file(problem, options.path);
  nlohmann::json out{{"valid", result.valid}, {"reason", result.reason}};
  if (result.segment) out["segment"] = *result.segment;
  if (!options.json.empty()) write_json(out, options.json);
  if (options.json != "-") std::cout << (result.valid ? "valid" : "invalid: " + result.reason) << '\n';
  return result.valid ? ok : invalid_path;
}

}  // namespace

void add_check_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command =
      app.add_subcommand("check", "Check exactly whether a path is a free motion of a world's robot or an arm");
  command->add_option("problem", options->world, "World or arm file (JSON)")->required();
  command
      ->add_option("path", options->path,
                   "Path file {\"path\": [...]}: [x, y] points; a rotating robot's [x, y, degrees] or [x, y, sin, "
                   "cos] poses; an arm's joint angles; for a car, its segments as plan --json writes them")
      ->required();
  command->add_option("--json", options->json,
                      "Write {\"valid\", \"reason\"} as JSON to this file ('-' for standard output)");
  command->callback([options, &run] { run = [options] { return run_check(*options); }; });
}

}  // namespace polyplan::cli
