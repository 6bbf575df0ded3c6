// polyplan plan WORLD.json [--planner NAME] [--option NAME=VALUE]... [--NAME VALUE]...
//                         [--json FILE|-] [--svg OUT.svg] [--trace FILE|-]
// The world's queries answered by one planner, built once: a translating robot's planner
// (planners<TranslatingRobot>), a rotating robot's (planners<RotatingRobot>) or, when the world's
// robot is a car, a car's (planners<SteeredCar>; its first, hybrid-astar, unless --planner says otherwise).
#include "cli/command.hpp"
#include "cli/planner_choice.hpp"
#include "cli/report_output.hpp"
#include "cli/trace_output.hpp"

#include <polyplan/draw/car_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <iostream>
#include <type_traits>

namespace polyplan::cli {
namespace {

struct PlanCommand {
  std::string world;
  std::string json;
  std::string svg;
  std::string trace;
  std::unique_ptr<PlannerChoice<TranslatingRobot, RotatingRobot, SteeredCar>> planner;
};

// Every expansion of each query's graph search, as JSON lines: the vertex's index in the graph the
// planner searched, and where it is ("at"). Planners that search no graph record none.
template <class Configuration>
void write_trace(const std::string& target, const World& world, const std::vector<PlanReport<Configuration>>& reports,
                 const std::string& planner) {
  TraceOutput trace(target);
  std::size_t lines = 0;
  for (std::size_t i = 0; i < reports.size(); ++i)
    for (const PlanExpansion<Configuration>& e : reports[i].trace) {
      auto line = expansion_line(e.step, e.vertex, e.g, e.h, e.f,
                                 e.backpointer ? nlohmann::ordered_json(*e.backpointer) : nlohmann::ordered_json(nullptr), e.open);
      if constexpr (std::is_same_v<Configuration, ExactPoint>) line["at"] = {to_double(e.at.x), to_double(e.at.y)};
      line["query"] = world.queries[i].name;
      trace.line(line);
      ++lines;
    }
  trace.finish();
  if (lines == 0)
    std::cerr << "warning: --trace: " << planner << " ran no graph search for these queries (the graph planners record one: "
              << "visibility, visibility-full, trapezoid, voronoi, raster, gvd-grid)\n";
}

// The queries answered, printed and drawn; `problem` is what the space's planners are built from.
template <class Space>
int answer(const PlanCommand& command, const World& world, const typename Space::Problem& problem) {
  const auto planner = command.planner->make<Space>(problem);
  std::vector<PlanReport<typename Space::Configuration>> reports;
  QueryOptions query_options;
  query_options.record = !command.svg.empty();  // the picture shows the roadmap and the search
  query_options.trace = !command.trace.empty();
  for (const Query& q : world.queries) reports.push_back(planner->plan(q, query_options));

  if (!command.trace.empty()) write_trace(command.trace, world, reports, command.planner->name());
  if (!command.svg.empty()) draw_plan(problem, reports).write(command.svg);
  if (!command.json.empty()) {
    nlohmann::json answers = nlohmann::json::array();
    for (std::size_t i = 0; i < reports.size(); ++i) answers.push_back(plan_json(reports[i], world.queries[i].name));
    write_json(one_or_array(std::move(answers)), command.json);
  }
  if (command.json != "-" && command.trace != "-") {
    const std::string steps = std::is_same_v<Space, RotatingRobot> ? "motion" : "segment";  // a car's: arcs and straights
    for (std::size_t i = 0; i < reports.size(); ++i) std::cout << report_line(world.queries[i].name, reports[i], "", steps) << '\n';
    if (!command.svg.empty()) std::cout << "picture: " << command.svg << '\n';
  }
  return ok;
}

int run_plan(const PlanCommand& command) {
  std::vector<std::string> warnings;
  const World world = read_world(command.world, &warnings);
  print_warnings(warnings);
  if (world.robot.car) {
    command.planner->prefer<SteeredCar>();
    command.planner->default_to(planners<SteeredCar>().entries().front().name);  // the registry lists a space's default first
  } else {
    command.planner->prefer<TranslatingRobot>();
    // A world that changes goes to the first planner that follows its changes, unless one is named.
    if (!world.changes.empty()) command.planner->default_to(planners_following_changes().front());
  }
  command.planner->values();  // a bad planner or option is reported before any planning
  if (command.json == "-" && command.trace == "-")
    throw InputError("--json - and --trace -: only one of them can go to standard output");
  if (command.planner->chose<SteeredCar>()) {
    require_plannable_queries(world, nullptr, command.planner->name());
    return answer<SteeredCar>(command, world, world);
  }
  if (command.planner->chose<RotatingRobot>()) {
    require_plannable_queries(world, nullptr, command.planner->name());
    return answer<RotatingRobot>(command, world, world);
  }
  const CSpace cspace(world);
  require_plannable_queries(world, &cspace, command.planner->name());
  return answer<TranslatingRobot>(command, world, cspace);
}

}  // namespace

void add_plan_command(CLI::App& app, Action& run) {
  auto command = std::make_shared<PlanCommand>();
  CLI::App* plan = app.add_subcommand("plan", "Paths for the world's queries from one planner (polyplan planners lists them)");
  plan->add_option("world", command->world, "World file (JSON)")->required();
  plan->add_option("--json", command->json, "Write the plan(s) as JSON to this file ('-' for standard output)");
  plan->add_option("--svg", command->svg, "Draw world, C-obstacles, the planner's roadmap or cells, and the path(s)");
  plan->add_option("--trace", command->trace,
                   "Graph planners: every expansion of the search as a JSON line {step, vertex, g, h, f, backpointer, open, "
                   "at, query} to this file ('-' for standard output)");
  command->planner = std::make_unique<PlannerChoice<TranslatingRobot, RotatingRobot, SteeredCar>>(
      *plan, "--planner", std::vector<std::string>{"--roadmap"}, "visibility",
      std::set<std::string>{"--planner", "--roadmap", "--option", "--json", "--svg", "--trace", "--help"});
  plan->callback([command, &run] { run = [command] { return run_plan(*command); }; });
}

}  // namespace polyplan::cli
