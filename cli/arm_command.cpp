// polyplan arm ARM.json --method grid --resolution DEG [--no-torus] [--lazy|--eager] [--json -]
//                        [--svg OUT.svg] [--strobe OUT.svg]: an n-link arm planned on a grid over
// its C-space, every query of the file (or the one --query names).
#include "cli/command.hpp"

#include <polyplan/arm/arm_grid_planner.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace polyplan::cli {
namespace {

struct ArmCommandOptions {
  std::string file;
  std::string method = "grid";
  double resolution = 5;
  double check = 0;
  bool no_torus = false;
  bool lazy = true;  // the default; --lazy only says so
  bool eager = false;
  std::string search = "astar";
  double weight = 1;
  std::string query;
  std::string json;
  std::string svg;
  std::string strobe;
  std::size_t every = 0;
};

// OUT.svg for a single query; OUT-NAME.svg for each of several.
std::string picture_path(const std::string& base, const std::string& query, std::size_t queries) {
  if (queries == 1) return base;
  std::string name;
  for (char c : query) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  const auto dot = base.rfind(".svg");
  return (dot == std::string::npos ? base : base.substr(0, dot)) + "-" + name + ".svg";
}

std::string degrees_text(double d) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", d);
  return text;
}

// The configurations the motion passes through, every check step, for the pictures.
std::vector<JointAngles> dense_motion(const std::vector<JointAngles>& path, double check_degrees) {
  std::vector<JointAngles> motion;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    auto samples = motion_samples(path[k], path[k + 1], check_degrees * two_pi / 360);
    motion.insert(motion.end(), samples.begin() + (k == 0 ? 0 : 1), samples.end());
  }
  if (path.size() == 1) motion = path;
  return motion;
}

nlohmann::json plan_json(const ArmQuery& query, const ArmGridPlan& plan, const ArmGridOptions& options) {
  nlohmann::json path = nlohmann::json::array();
  for (const auto& q : plan.path) path.push_back(q);
  nlohmann::json j{{"query", query.name},
                   {"found", plan.found},
                   {"length", plan.found ? nlohmann::json(plan.length) : nlohmann::json(nullptr)},
                   {"path", path},
                   {"cells_evaluated", plan.cells_evaluated},
                   {"moves_checked", plan.moves_checked},
                   {"expanded", plan.expanded},
                   {"seconds", plan.seconds},
                   {"grid",
                    {{"resolution_degrees", options.resolution_degrees},
                     {"cells_per_axis", plan.cells_per_axis},
                     {"torus", options.torus},
                     {"evaluation", options.lazy ? "lazy" : "eager"},
                     {"check_degrees", plan.check_degrees}}},
                   {"search", {{"algorithm", std::string(to_string(options.search.algorithm))}, {"generated", plan.generated}}}};
  if (!plan.found) j["why_not"] = plan.why_not;
  return j;
}

int run_arm(const ArmCommandOptions& o) {
  if (o.method != "grid") throw InputError("--method " + o.method + ": only grid is available");
  const ArmProblem problem = read_arm_problem(o.file);
  std::vector<const ArmQuery*> queries;
  for (const auto& q : problem.queries)
    if (o.query.empty() || q.name == o.query) queries.push_back(&q);
  if (problem.queries.empty()) throw InputError(o.file + ": no start/goal and no queries to plan");
  if (queries.empty()) throw InputError(o.file + ": no query named " + o.query);

  ArmGridOptions options;
  options.resolution_degrees = o.resolution;
  options.check_degrees = o.check;
  options.torus = !o.no_torus;
  options.lazy = !o.eager;
  const auto algorithm = search_from_string(o.search);
  if (!algorithm) throw InputError("--search " + o.search + ": expected astar, dijkstra, bfs, dfs, greedy or wastar");
  options.search = {*algorithm, o.weight};
  if (*algorithm == Search::wastar && !(o.weight >= 1)) throw InputError("--weight must be at least 1");
  options.keep_cspace = !o.svg.empty() || !o.strobe.empty();

  nlohmann::json answers = nlohmann::json::array();
  for (const ArmQuery* query : queries) {
    ArmGridPlan plan;
    try {
      plan = plan_arm_on_grid(problem, *query, options);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.file + ": " + e.what());
    }
    answers.push_back(plan_json(*query, plan, options));
    if (o.json.empty()) {
      std::printf("%s: %s", query->name.c_str(), plan.found ? "found" : "no path");
      if (plan.found) std::printf(", length %.4f rad, %zu configurations", plan.length, plan.path.size());
      else std::printf(" (%s)", plan.why_not.c_str());
      std::printf("; %zu cells evaluated, %zu moves checked, %zu expanded, %.4f s\n", plan.cells_evaluated,
                  plan.moves_checked, plan.expanded, plan.seconds);
    }
    if (!o.svg.empty() || !o.strobe.empty()) {
      ArmPlanPicture picture;
      picture.problem = &problem;
      picture.motion = dense_motion(plan.path, plan.check_degrees);
      picture.torus = options.torus;
      picture.title = o.file.substr(o.file.find_last_of('/') + 1) + " · " + query->name + " · " +
                      (options.torus ? "torus" : "no torus") + " · " + degrees_text(o.resolution) + "°";
      if (!plan.cspace.empty()) picture.cspace = ArmCSpaceImage{plan.cells_per_axis, plan.cspace};
      try {
        if (!o.svg.empty()) write_arm_animation_svg(picture_path(o.svg, query->name, queries.size()), picture);
        if (!o.strobe.empty()) {
          const std::size_t every = o.every ? o.every : std::max<std::size_t>(1, picture.motion.size() / 12);
          write_arm_strobe_svg(picture_path(o.strobe, query->name, queries.size()), picture, every);
        }
      } catch (const std::runtime_error& e) {
        throw InputError(e.what());
      }
    }
  }
  if (!o.json.empty()) write_json(answers.size() == 1 ? answers[0] : answers, o.json);
  return ok;
}

}  // namespace

void add_arm_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<ArmCommandOptions>();
  auto* cmd = app.add_subcommand("arm", "plan an n-link arm's motion on a grid over its C-space (torus by default)");
  cmd->add_option("arm", options->file, "arm file (JSON: links, link_width, obstacles, points, start/goal or queries)")
      ->required();
  cmd->add_option("--method", options->method, "planner: grid")->capture_default_str();
  cmd->add_option("--resolution", options->resolution, "grid step in degrees (must divide 360)")->capture_default_str();
  cmd->add_option("--check-resolution", options->check,
                  "check motions every this many degrees of every joint (default: min(1, resolution))");
  cmd->add_flag("--no-torus", options->no_torus, "joint angles are the interval [0, 2pi): no turning across 0");
  auto* lazy = cmd->add_flag("--lazy", options->lazy, "decide cells when the search reaches them (default)");
  cmd->add_flag("--eager", options->eager, "evaluate every cell before searching")->excludes(lazy);
  cmd->add_option("--search", options->search, "astar, dijkstra, bfs, dfs, greedy or wastar")->capture_default_str();
  cmd->add_option("--weight", options->weight, "weighted A*: f = g + weight * h");
  cmd->add_option("--query", options->query, "plan only the query with this name (e.g. easy)");
  cmd->add_option("--json", options->json, "write the answer as JSON to this file ('-' for standard output)");
  cmd->add_option("--svg", options->svg, "write an SVG animation of the motion (and, for 2 joints, the C-space)");
  cmd->add_option("--strobe", options->strobe, "write an SVG with every k-th configuration drawn");
  cmd->add_option("--every", options->every, "k for --strobe (default: about 12 configurations)");
  cmd->callback([options, &run] { run = [options] { return run_arm(*options); }; });
}

}  // namespace polyplan::cli
