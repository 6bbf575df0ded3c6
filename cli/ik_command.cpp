// polyplan ik ARM.json --target X,Y [--orientation DEG] [--all] [--collision-free] [--json FILE|-]
// [--svg OUT.svg]: joint angles that put the arm's hand at the target (arm/inverse_kinematics.hpp:
// closed form for two links, and for three with an orientation; damped least squares and FABRIK
// otherwise; within the arm file's joint limits), each with its end-effector error, optionally only
// those free of the obstacles; the picture draws every solution at once.
#include "cli/command.hpp"

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/inverse_kinematics.hpp>
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/arm_reader.hpp>

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

IkOptions ik_options(const Arm& arm, const IkCommandOptions& o) {
  IkOptions options;
  if (!o.orientation.empty()) options.orientation = degrees_option(o.orientation, "--orientation") * M_PI / 180;
  options.limits = arm.limits;
  options.all = o.all;
  options.seeds = o.all ? 32 : 8;
  return options;
}

int run_ik(const IkCommandOptions& o) {
  std::vector<std::string> warnings;
  const ArmProblem problem = read_arm_problem(o.arm, &warnings);
  print_warnings(warnings);
  const std::vector<double> t = comma_numbers(o.target, "--target");
  if (t.size() != 2) throw InputError("--target " + o.target + ": expected X,Y");
  const Eigen::Vector2d target(t[0], t[1]);
  IkOptions options = ik_options(problem.arm, o);
  options.exact_target = exact_target(o.target);
  IkAnswer answer = inverse_kinematics(problem.arm, target, options);
  std::vector<bool> free;
  const ArmCollisionChecker checker(problem);
  for (const IkSolution& s : answer.solutions) free.push_back(checker.is_free(s.angles));
  if (o.collision_free && answer.found) {
    IkAnswer kept{false, {}, ""};
    for (std::size_t i = 0; i < answer.solutions.size(); ++i)
      if (free[i]) kept.solutions.push_back(answer.solutions[i]);
    kept.found = !kept.solutions.empty();
    if (!kept.found) kept.why_not = "every solution collides", kept.solutions = answer.solutions;
    else free.assign(kept.solutions.size(), true);
    answer = std::move(kept);
  }
  if (!o.json.empty()) {
    nlohmann::json solutions = nlohmann::json::array();
    for (std::size_t i = 0; i < answer.solutions.size(); ++i)
      solutions.push_back(
          {{"angles", answer.solutions[i].angles}, {"error", answer.solutions[i].error}, {"free", bool(free[i])}});
    nlohmann::json out = {{"target", {target.x(), target.y()}}, {"found", answer.found}, {"solutions", solutions}};
    out["orientation"] = o.orientation.empty() ? nlohmann::json(nullptr)
                                               : nlohmann::json(degrees_option(o.orientation, "--orientation"));
    if (!answer.found) out["why_not"] = answer.why_not;
    write_json(out, o.json);
  }
  if (!o.svg.empty()) {
    ArmPlanPicture picture;
    picture.problem = &problem;
    picture.target = WorkspaceGoal{target, options.orientation};
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < answer.solutions.size(); ++i) {
      picture.motion.push_back(answer.solutions[i].angles);
      char label[96];
      std::snprintf(label, sizeof label, "%s %zu, error %.2g%s", answer.found ? "solution" : "closest", i + 1,
                    answer.solutions[i].error, free[i] ? "" : ", collides");
      labels.push_back(label);
    }
    picture.title = "inverse kinematics: the hand at " + o.target;
    draw_arm_configurations(picture, labels).write(o.svg);
  }
  if (o.json != "-") {
    std::cout << (answer.found ? std::to_string(answer.solutions.size()) + " solution(s)"
                               : "no solution (" + answer.why_not + "); the closest")
              << " for the hand at (" << target.x() << ", " << target.y() << "):\n";
    for (std::size_t i = 0; i < answer.solutions.size(); ++i) {
      std::cout << " ";
      for (const double a : answer.solutions[i].angles) std::cout << ' ' << a;
      char error[32];
      std::snprintf(error, sizeof error, "%.3g", answer.solutions[i].error);
      std::cout << " rad, error " << error << (free[i] ? "" : ", collides") << '\n';
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
