// polyplan plan WORLD.json [--roadmap visibility|visibility-full] [--search ...] [--weight W]
//                         [--json -] [--svg OUT.svg]
// Shortest paths for the world's queries, all from one roadmap.
#include "cli/command.hpp"
#include "cli/plan_output.hpp"

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <iostream>

namespace polyplan::cli {
namespace {

struct PlanOptions {
  std::string world;
  std::string roadmap = "visibility";
  std::string search = "astar";
  double weight = 1.0;
  std::string json;
  std::string svg;
};

void draw(const CSpace& cspace, const VisibilityGraph& graph, const std::vector<Plan>& plans, const std::string& file) {
  svg::Drawing drawing(view_box(cspace.world(), cspace));
  draw_cspace(drawing, cspace);
  draw_roadmap(drawing, graph.roadmap(), graph.facts().vertices);
  std::vector<ExactPoint> expanded;
  for (const Plan& p : plans) expanded.insert(expanded.end(), p.expanded_points.begin(), p.expanded_points.end());
  draw_points(drawing, expanded, "expanded by the search");
  static const char* const palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2"};
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (plans[i].found)
      draw_path(drawing, plans[i].path, plans.size() == 1 ? "path" : "path " + std::to_string(i), palette[i % 7]);
  drawing.write(file);
}

int run_plan(const PlanOptions& options) {
  const auto algorithm = search_from_string(options.search);
  if (!algorithm) throw InputError("--search: unknown algorithm \"" + options.search + "\"");
  if (!(options.weight >= 1.0)) throw InputError("--weight: must be at least 1, got " + std::to_string(options.weight));
  if (options.roadmap != "visibility" && options.roadmap != "visibility-full")
    throw InputError("--roadmap: unknown roadmap \"" + options.roadmap + "\" (visibility, visibility-full)");

  std::vector<std::string> warnings;
  const World world = read_world(options.world, &warnings);
  print_warnings(warnings);
  if (world.queries.empty()) throw InputError(options.world + ": world: no start/goal and no queries to plan");
  const CSpace cspace(world);
  cspace.require_free_queries();
  VisibilityGraph graph(cspace, options.roadmap == "visibility" ? VisibilityKind::reduced : VisibilityKind::full);

  std::vector<Plan> plans;
  SearchOptions search{*algorithm, options.weight};
  search.record_expanded = !options.svg.empty();  // the picture shows them
  for (const Query& q : world.queries) plans.push_back(graph.plan(q.start, q.goal, search));

  if (!options.svg.empty()) draw(cspace, graph, plans, options.svg);
  if (!options.json.empty()) {
    nlohmann::json out = nlohmann::json::array();
    for (const Plan& p : plans) out.push_back(plan_json(p));
    write_json(plans.size() == 1 ? out[0] : out, options.json);
  }
  if (options.json != "-") {
    for (std::size_t i = 0; i < plans.size(); ++i) print_plan(std::cout, world.queries[i], plans[i]);
    if (!options.svg.empty()) std::cout << "picture: " << options.svg << '\n';
  }
  return ok;
}

}  // namespace

void add_plan_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* command = app.add_subcommand("plan", "Shortest paths for the world's queries on an exact roadmap");
  command->add_option("world", options->world, "World file (JSON)")->required();
  command->add_option("--roadmap", options->roadmap, "visibility (reduced: bitangents between corners) or visibility-full")
      ->capture_default_str();
  command->add_option("--search", options->search, "astar, dijkstra, bfs, dfs, greedy or wastar")->capture_default_str();
  command->add_option("--weight", options->weight, "Weighted A*: f = g + weight * h (weight >= 1)")->capture_default_str();
  command->add_option("--json", options->json, "Write the plan(s) as JSON to this file ('-' for standard output)");
  command->add_option("--svg", options->svg, "Draw world, C-obstacles, roadmap and path(s)");
  command->callback([options, &run] { run = [options] { return run_plan(*options); }; });
}

}  // namespace polyplan::cli
