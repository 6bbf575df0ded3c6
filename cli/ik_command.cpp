// polyplan ik ARM.json --target X,Y [--orientation DEG] [--all] [--collision-free] [--json FILE|-]
// [--svg OUT.svg]: joint angles that put the arm's hand at the target (arm/inverse_kinematics.hpp:
// closed form for two links, and for three with an orientation; damped least squares and FABRIK
// otherwise; within the arm file's joint limits), each with its end-effector error, optionally only
// those free of the obstacles; the picture draws every solution at once.
#include "cli/command.hpp"

#include <polyplan/arm/ik_study.hpp>
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/registry/ik_json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace polyplan::cli {
namespace {

struct IkCommandOptions {
  std::string arm, target;
  std::string orientation;  // degrees as written; empty: not asked
  bool all = false, collision_free = false;
  std::string json, svg;
};

// The target as written ("0.3,0.4" is (3/10, 2/5)), which decides a two-link arm's boundary
// exactly; nothing when a part is not an exact number (a hexadecimal double: its double is exact).
std::optional<ExactPoint> exact_target(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const auto x = parse_rational(text.substr(0, comma)), y = parse_rational(text.substr(comma + 1));
  if (!x || !y) return std::nullopt;
  return ExactPoint{*x, *y};
}

int run_ik(const IkCommandOptions& o) {
  std::vector<std::string> warnings;
  const ArmProblem problem = read_arm_problem(o.arm, &warnings);
  print_warnings(warnings);
  const std::vector<double> t = comma_numbers(o.target, "--target");
  if (t.size() != 2) throw InputError("--target " + o.target + ": expected X,Y");
  IkRequest request;
  request.target = {t[0], t[1]};
  request.exact_target = exact_target(o.target);
  if (!o.orientation.empty()) request.orientation_degrees = degrees_option(o.orientation, "--orientation");
  request.all = o.all;
  request.collision_free = o.collision_free;
  const IkStudy study = study_ik(problem, request);
  const IkAnswer& answer = study.answer;
  if (!o.json.empty()) write_json(ik_json(request, study), o.json);
  if (!o.svg.empty())
    draw_ik_study(problem, request, study, "inverse kinematics: the hand at " + o.target).write(o.svg);
  if (o.json != "-") {
    std::cout << (answer.found ? std::to_string(answer.solutions.size()) + " solution(s)"
                               : "no solution (" + answer.why_not + "); the closest")
              << " for the hand at (" << request.target.x() << ", " << request.target.y() << "):\n";
    for (std::size_t i = 0; i < answer.solutions.size(); ++i) {
      std::cout << " ";
      for (const double a : answer.solutions[i].angles) std::cout << ' ' << a;
      char error[32];
      std::snprintf(error, sizeof error, "%.3g", answer.solutions[i].error);
      std::cout << " rad, error " << error << (study.free[i] ? "" : ", collides") << '\n';
    }
    if (!o.svg.empty()) std::cout << "picture: " << o.svg << '\n';
  }
  return ok;
}

}  // namespace

void add_ik_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<IkCommandOptions>();
  CLI::App* command = app.add_subcommand("ik", "Joint angles that put an arm's hand at a point (inverse kinematics)");
  command->add_option("arm", options->arm, "arm file (JSON)")->required();
  command->add_option("--target", options->target, "where the hand goes, X,Y")->required();
  command->add_option("--orientation", options->orientation,
                      "the last link's absolute angle there, degrees (reduced exactly into (-180, 180])");
  command->add_flag("--all", options->all,
                    "every distinct solution found (numeric: from 32 seeds), not only the first");
  command->add_flag("--collision-free", options->collision_free, "only solutions free of the arm file's obstacles");
  command->add_option("--json", options->json,
                      "write {target, found, solutions [{angles, error, free}]} as JSON ('-' for standard output)");
  command->add_option("--svg", options->svg, "draw every solution at once");
  command->callback([options, &run] { run = [options] { return run_ik(*options); }; });
}

}  // namespace polyplan::cli
