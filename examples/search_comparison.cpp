// The table of the course's C-space and visibility-graph problem set's report: on the the course's C-space and
// visibility-graph problem set world, every search of a course over one visibility graph — number of path segments,
// path cost, nodes explored — and all paths in one picture. Usage: search_comparison [WORLD.json] [OUT.svg]
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  using namespace polyplan;
  const std::string world_file = argc > 1 ? argv[1] : POLYPLAN_DATA_DIR "/worlds/seed004.json";
  const std::string picture = argc > 2 ? argv[2] : "search_comparison.svg";
  try {
    const World world = read_world(world_file);
    if (world.queries.empty()) throw InputError(world_file + ": world: needs a start and a goal");
    const CSpace cspace(world);
    cspace.require_free_queries();
    VisibilityGraph graph(cspace, VisibilityKind::full);  // the graph a course draws: every visible pair
    const Query& query = world.queries.front();

    // DFS in the palette's grey, so that its wandering path does not hide the others.
    struct Row {
      const char* name;
      SearchOptions options;
      std::size_t colour;  // in the theme's path palette
    } rows[] = {{"DFS", {Search::dfs}, 9},
                {"BFS", {Search::bfs}, 1},
                {"UCS (Dijkstra)", {Search::dijkstra}, 4},
                {"A* (admissible)", {Search::astar}, 2},
                {"Weighted A* (w = 3)", {Search::wastar, 3.0}, 0},
                {"Greedy best-first", {Search::greedy}, 3}};

    // One recorded query gives the graph to draw; every row then searches the same graph.
    const PlanReport<ExactPoint> first = graph.plan(query, QueryOptions{true});
    svg::Drawing drawing(view_box(world, cspace));
    draw_cspace(drawing, cspace);
    draw_graph(drawing, *first.recording.graph);
    std::printf("%s: visibility graph with %lld vertices and %lld edges\n\n", world_file.c_str(),
                static_cast<long long>(first.facts.at(RoadmapFacts::vertices)),
                static_cast<long long>(first.facts.at(RoadmapFacts::edges)));
    std::printf("%-22s %22s %12s %20s\n", "Algorithm", "# of segments in path", "path cost", "# of nodes explored");
    for (const Row& row : rows) {
      const PlanReport<ExactPoint> plan = graph.plan(query, row.options);
      if (!plan.found) {
        std::printf("%-22s %22s\n", row.name, "no path");
        continue;
      }
      std::printf("%-22s %22zu %12.2f %20lld\n", row.name, plan.path.size() - 1, plan.length,
                  static_cast<long long>(plan.facts.at(SearchFacts::expanded)));
      draw_path(drawing, plan.path, row.name, theme::path_colour(row.colour));
    }
    drawing.write(picture);
    std::printf("\npicture: %s\n", picture.c_str());
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
