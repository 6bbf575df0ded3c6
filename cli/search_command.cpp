// polyplan search GRAPH.json --start I --goal J [--method astar|dijkstra|bfs|dfs|greedy|wastar|uniform-cost]
// [--weight W] [--reopen] [--json FILE|-] [--trace FILE|-] [--svg OUT.svg [--animate]] [--edge-weights]
// [--labels] [--backpointers] [--heuristic] [--indices]: a graph search on the course's graph-search homework's
// graph_vector (io/graph_reader.hpp) with the Euclidean heuristic, to watch: every expansion as a JSON line, the final
// state or the whole search as a picture.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/trace_output.hpp"

#include <polyplan/draw/search_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/graph_reader.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace polyplan::cli {
namespace {

// --method, --weight and --reopen (h: the Euclidean distance to the goal).
struct GraphSearch {
  SearchOptions search{Search::astar, 1.5};
};
OptionTable<GraphSearch> graph_search_table() {
  OptionTable<GraphSearch> table;
  Choices<Search> methods = search_choices();
  for (const auto& [name, algorithm] : course_search_names) methods.emplace_back(name, algorithm);
  return add_search_options(table, &GraphSearch::search, "method", methods);
}

struct SearchCommandOptions {
  std::string graph;
  long long start = -1, goal = -1;
  std::unique_ptr<CommandOptions<GraphSearch>> search;
  std::string json, svg, trace;
  bool animate = false;
  SearchPictureOptions picture;
};

DigraphVertexId vertex_option(long long index, const char* option, const GraphFile& file) {
  const std::size_t n = file.vertices.size();
  if (index < 0 || static_cast<unsigned long long>(index) >= n)
    throw InputError(std::string(option) + " " + std::to_string(index) + ": not a vertex of " + file.source +
                     " (0-based indices [0, " + std::to_string(n) + "))");
  return static_cast<DigraphVertexId>(index);
}

SearchOptions search_options(const SearchCommandOptions& o) {
  SearchOptions options = o.search->parse().search;
  options.record_expanded = true;
  options.record_trace = true;  // the picture's open list, labels and arrows come from it
  options.ties_first_discovered =
      true;  // the course's graph-search homework's order: any A* that breaks ties so expands the same vertices
  return options;
}

nlohmann::ordered_json result_json(const SearchResult<DigraphVertexId>& r, const SearchOptions& options,
                                   DigraphVertexId start, DigraphVertexId goal) {
  nlohmann::ordered_json out;
  out["found"] = r.found;
  out["method"] = std::string(to_string(r.algorithm));
  if (r.algorithm == Search::wastar) {
    out["weight"] = options.weight;
    out["reopen"] = options.reopen;
  }
  out["start"] = start;
  out["goal"] = goal;
  out["path"] = r.path;
  out["cost"] = r.found ? nlohmann::ordered_json(r.cost) : nlohmann::ordered_json(nullptr);
  out["expanded"] = r.expanded;
  out["generated"] = r.generated;
  out["expansion_order"] = r.expanded_order;
  nlohmann::ordered_json expansions = nlohmann::ordered_json::array();
  for (const auto& e : r.trace.expansions) expansions.push_back(expansion_line(e));
  out["expansions"] = expansions;
  out["seconds"] = r.seconds;
  return out;
}

// nlohmann::json would sort the keys: written in their order.
void write_result(const nlohmann::ordered_json& value, const std::string& target) {
  write_json_text(value.dump(2), target);
}

std::string summary_line(const SearchResult<DigraphVertexId>& r) {
  std::string line = std::string(to_string(r.algorithm)) + ": ";
  if (r.found) {
    char cost[64];
    std::snprintf(cost, sizeof cost, "cost %.6g, ", r.cost);
    std::string path;
    for (const DigraphVertexId v : r.path) path += (path.empty() ? "" : " ") + std::to_string(v);
    line += "path " + path + ", " + cost;
  } else {
    line += "no path, ";
  }
  return line + "expanded " + std::to_string(r.expanded) + " of " + std::to_string(r.generated) + " generated";
}

int run_search(const SearchCommandOptions& o) {
  if (o.animate && o.svg.empty()) throw InputError("--animate: give --svg OUT.svg for the animation");
  if (o.json == "-" && o.trace == "-")
    throw InputError("--json - and --trace -: only one of them can go to standard output");
  const SearchOptions options = search_options(o);
  std::vector<std::string> warnings;
  const GraphFile file = read_graph(o.graph, &warnings);
  print_warnings(warnings);
  const DigraphVertexId start = vertex_option(o.start, "--start", file), goal = vertex_option(o.goal, "--goal", file);
  const WeightedDigraph graph = make_weighted_digraph(file.vertices);
  const SearchResult<DigraphVertexId> result = shortest_path(graph, start, goal, options);

  if (!o.trace.empty()) {
    TraceOutput trace(o.trace);
    for (const auto& e : result.trace.expansions) trace.line(expansion_line(e));
    trace.finish();
  }
  if (!o.json.empty()) write_result(result_json(result, options, start, goal), o.json);
  if (!o.svg.empty()) {
    const std::string title = search_title(o.graph, result, start, goal);
    (o.animate ? draw_search_animation(graph, start, goal, result, o.picture, title)
               : draw_search(graph, start, goal, result, o.picture, title))
        .write(o.svg);
  }
  if (o.json != "-" && o.trace != "-") {
    std::cout << summary_line(result) << '\n';
    if (!o.svg.empty()) std::cout << "picture: " << o.svg << '\n';
  }
  return ok;
}

}  // namespace

void add_search_command(CLI::App& app, Action& run) {
  auto o = std::make_shared<SearchCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "search", "Search a graph given as the course's graph-search homework's vertex list, and watch the search");
  command
      ->add_option("graph", o->graph,
                   "Graph file (JSON): [{\"x\": [x, y], \"neighbors\": [...], \"neighbors_cost\": [...]}, ...]")
      ->required();
  command->add_option("--start", o->start, "Start vertex (0-based index)")->required();
  command->add_option("--goal", o->goal, "Goal vertex (0-based index)")->required();
  o->search = std::make_unique<CommandOptions<GraphSearch>>(*command, graph_search_table());
  command->add_option("--json", o->json,
                      "Write the result as JSON to this file ('-' for standard output): found, path, cost, expanded, "
                      "generated, expansion_order, expansions");
  command->add_option("--trace", o->trace,
                      "Every expansion as a JSON line {step, vertex, g, h, f, backpointer, open} to this file ('-' for "
                      "standard output)");
  command->add_option("--svg", o->svg, "Draw the graph, the expanded vertices, the open list and the path (SVG)");
  command->add_flag("--animate", o->animate, "Make the --svg picture an animation, one step per expansion");
  command->add_flag("--edge-weights", o->picture.edge_weights, "Picture: each edge's cost (off by default)");
  command->add_flag("--labels", o->picture.labels,
                    "Picture: g, h and f beside each vertex the search reached (off by default)");
  command->add_flag("--backpointers", o->picture.backpointers,
                    "Picture: an arrow from each such vertex to its backpointer (off by default)");
  command->add_flag("--heuristic", o->picture.heuristic, "Picture: h below every vertex (off by default)");
  command->add_flag("--indices", o->picture.indices, "Picture: each vertex's index (off by default)");
  command->callback([o, &run] { run = [o] { return run_search(*o); }; });
}

}  // namespace polyplan::cli
