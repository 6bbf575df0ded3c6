// polyplan arm ARM.json [--method NAME] [--option NAME=VALUE]... [--NAME VALUE]... [--query NAME]
//                       [--json FILE|-] [--svg OUT.svg] [--strobe OUT.svg [--every K]]
// An n-link arm's queries answered by one arm planner of the registry, built once; every query of
// the file, or the one --query names. A query whose goal is a point for the hand is planned to its
// goal set (arm/arm_goal_set.hpp); the summary line says which IK solution the path reaches, and
// the pictures mark the point.
#include "cli/command.hpp"
#include "cli/planner_choice.hpp"
#include "cli/report_output.hpp"

#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>

#include <cctype>
#include <iostream>

namespace polyplan::cli {
namespace {

struct ArmCommand {
  std::string file;
  std::string query;
  std::string json;
  std::string svg;
  std::string strobe;
  std::size_t every = 0;
  bool check_resolution = false;  // given: refused, since motions are certified, not sampled
  std::unique_ptr<PlannerChoice<PlanarArm>> planner;
};

// OUT.svg for a single query; OUT-NAME.svg for each of several.
std::string picture_path(const std::string& base, const std::string& query, std::size_t queries) {
  if (queries == 1) return base;
  std::string name;
  for (char c : query) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  const auto dot = base.rfind(".svg");
  return (dot == std::string::npos ? base : base.substr(0, dot)) + "-" + name + ".svg";
}

std::string file_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

int run_arm(const ArmCommand& command) {
  command.planner->values();  // a bad planner or option is reported before any work
  if (command.check_resolution)
    throw InputError("--check-resolution is gone: every motion is certified free (conservative advancement), not "
                     "sampled at a resolution; leave the option out");
  const ArmProblem problem = read_arm_problem(command.file);
  if (problem.queries.empty()) throw InputError(command.file + ": no start/goal and no queries to plan");
  std::vector<const ArmQuery*> queries;
  for (const auto& q : problem.queries)
    if (command.query.empty() || q.name == command.query) queries.push_back(&q);
  if (queries.empty()) throw InputError(command.file + ": no query named " + command.query);
  const auto planner = command.planner->make<PlanarArm>(problem);

  const bool pictures = !command.svg.empty() || !command.strobe.empty();
  nlohmann::json answers = nlohmann::json::array();
  for (const ArmQuery* query : queries) {
    const PlanReport<JointAngles> report = planner->plan(*query, QueryOptions{pictures});
    answers.push_back(plan_json(report, query->name));
    if (command.json.empty()) std::cout << report_line(query->name, report, " rad", "motion") << '\n';
    if (!pictures) continue;
    std::string title = file_name(command.file) + " · " + query->name + " · " + command.planner->name();
    for (const auto& [name, value] : command.planner->values()) title += " · " + name + " " + value;
    try {
      using Kind = ArmPictureOptions::Kind;
      const ArmPictureOptions animation{Kind::animation, title, 0, 1, query->goal_point};
      const ArmPictureOptions strobe{Kind::strobe, title, command.every, 1, query->goal_point};
      if (!command.svg.empty()) draw_plan(problem, report, animation).write(picture_path(command.svg, query->name, queries.size()));
      if (!command.strobe.empty()) draw_plan(problem, report, strobe).write(picture_path(command.strobe, query->name, queries.size()));
    } catch (const std::runtime_error& e) {  // a picture that cannot be written
      throw InputError(e.what());
    }
  }
  if (!command.json.empty()) write_json(one_or_array(std::move(answers)), command.json);
  return ok;
}

}  // namespace

void add_arm_command(CLI::App& app, Action& run) {
  auto command = std::make_shared<ArmCommand>();
  CLI::App* arm = app.add_subcommand("arm", "Plan an n-link arm's motion with an arm planner (polyplan planners lists them)");
  arm->add_option("arm", command->file, "arm file (JSON: links, link_width, obstacles, points, start/goal or queries)")->required();
  arm->add_option("--query", command->query, "plan only the query with this name (e.g. easy)");
  arm->add_option("--json", command->json, "write the answer as JSON to this file ('-' for standard output)");
  arm->add_option("--svg", command->svg, "write an SVG animation of the motion (and, for 2 joints, the C-space)");
  arm->add_option("--strobe", command->strobe, "write an SVG with every k-th configuration drawn");
  arm->add_option("--every", command->every, "k for --strobe (default: about 12 configurations)");
  // An option that would do nothing is refused, not ignored: a script that passes it learns why.
  arm->add_option_function<double>(
         "--check-resolution", [command](double) { command->check_resolution = true; },
         "refused: motions are certified, not sampled")
      ->group("");
  command->planner = std::make_unique<PlannerChoice<PlanarArm>>(
      *arm, "--method", std::vector<std::string>{"--planner"}, "grid",
      std::set<std::string>{"--method", "--planner", "--option", "--query", "--json", "--svg", "--strobe", "--every",
                            "--check-resolution", "--help", "--lazy", "--eager"});
  // The grid planner's evaluation as the flags older scripts use.
  auto* lazy = command->planner->add_alias(*arm, "--lazy", "evaluation", "lazy", "decide cells when the search reaches them (default)");
  command->planner->add_alias(*arm, "--eager", "evaluation", "eager", "evaluate every cell before searching")->excludes(lazy);
  arm->callback([command, &run] { run = [command] { return run_arm(*command); }; });
}

}  // namespace polyplan::cli
