// draw/search_svg: the final state of a search and its animation, with Graph.plot's flags: one
// animated element per expanded vertex, labels g / h / f, backpointer arrows, the path.
#include <polyplan/draw/search_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/graph_reader.hpp>

#include "draw/svg_fixtures.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace polyplan;
using polyplan::test::count;

namespace {

struct Searched {
  WeightedDigraph graph;
  SearchResult<DigraphVertexId> result;
};

Searched searched(const std::string& name, DigraphVertexId start, DigraphVertexId goal,
                  Search algorithm = Search::astar) {
  std::vector<std::string> warnings;
  const GraphFile file = read_graph(std::string(POLYPLAN_SOURCE_DIR) + "/data/graphs/" + name, &warnings);
  Searched s{make_weighted_digraph(file.vertices), {}};
  SearchOptions options;
  options.algorithm = algorithm;
  options.record_expanded = true;
  options.record_trace = true;
  options.ties_first_discovered = true;
  s.result = shortest_path(s.graph, start, goal, options);
  return s;
}

SearchPictureOptions every_flag() {
  SearchPictureOptions options;
  options.edge_weights = options.labels = options.backpointers = options.heuristic = options.indices = true;
  return options;
}

}  // namespace

TEST(SearchSvg, AnimatesEachExpandedVertexOnce) {
  const Searched s = searched("grid_medium.json", 0, 37);
  ASSERT_TRUE(s.result.found);
  const std::string svg = draw_search_animation(s.graph, 0, 37, s.result, every_flag(), "medium").str();
  EXPECT_EQ(count(svg, "<circle class=\"expanded\""), s.result.expanded);
  // Each with its own <animate> inside, keyed at its step.
  for (auto pos = svg.find("<circle class=\"expanded\""); pos != std::string::npos;
       pos = svg.find("<circle class=\"expanded\"", pos + 1)) {
    const auto end = svg.find("</circle>", pos);
    EXPECT_NE(svg.substr(pos, end - pos).find("<animate attributeName=\"opacity\""), std::string::npos);
  }
  // Every vertex the search reached is in the open list for a while; one caption per step.
  std::size_t labelled = 0;
  std::vector<bool> seen(num_vertices(s.graph), false);
  for (const auto& l : s.result.trace.labels) labelled += !seen[l.vertex], seen[l.vertex] = true;
  EXPECT_EQ(count(svg, "<circle class=\"open\""), labelled);
  EXPECT_EQ(count(svg, "class=\"step\""), s.result.expanded);
  // A label and (but the start's) an arrow for each label the search set.
  EXPECT_EQ(count(svg, "class=\"label\""), s.result.trace.labels.size());
  EXPECT_EQ(count(svg, "<line class=\"backpointer\""), s.result.trace.labels.size() - 1);
  EXPECT_NE(svg.find("marker-end=\"url(#polyplan-backpointer)\""), std::string::npos);
  EXPECT_NE(svg.find(">g=0<"), std::string::npos) << "the start's label";
  EXPECT_NE(svg.find("path found, cost 16.83"), std::string::npos);
  EXPECT_NE(svg.find("repeatCount=\"indefinite\""), std::string::npos);
}

TEST(SearchSvg, DrawsTheFinalStateWithTheFlagsAsked) {
  const Searched s = searched("small.json", 0, 6);
  const std::string plain = draw_search(s.graph, 0, 6, s.result, {}, "small").str();
  EXPECT_NE(plain.find("expanded (6)"), std::string::npos);
  EXPECT_NE(plain.find("open list"), std::string::npos);
  EXPECT_NE(plain.find("path, cost 5"), std::string::npos);
  EXPECT_EQ(plain.find("g=0"), std::string::npos) << "labels are off by default";
  EXPECT_EQ(plain.find("<line class=\"backpointer\""), std::string::npos) << "arrows are off by default";
  EXPECT_EQ(plain.find("<animate"), std::string::npos);

  const std::string flagged = draw_search(s.graph, 0, 6, s.result, every_flag(), "small").str();
  for (const char* label : {">g=1.5<", ">h=3.162<", ">f=4.662<"})
    EXPECT_NE(flagged.find(label), std::string::npos) << label << " (vertex 1: h √10)";
  EXPECT_NE(flagged.find(">2.2<"), std::string::npos) << "the one-way edge's weight";
  EXPECT_EQ(count(flagged, "<line class=\"backpointer\""), 6u) << "every vertex reached but the start";
  EXPECT_NE(flagged.find("h=4<"), std::string::npos) << "the start's heuristic";
  EXPECT_EQ(count(flagged, ">h="), num_vertices(s.graph)) << "h once per vertex when labels and heuristic are both on";
  SearchPictureOptions labels_only;
  labels_only.labels = true;
  EXPECT_NE(draw_search(s.graph, 0, 6, s.result, labels_only, "small").str().find(">h=3.162<"), std::string::npos)
      << "without the heuristic flag the labels carry h";
}

TEST(SearchSvg, ASearchWithoutPathDrawsNoPath) {
  GraphFile lonely;
  lonely.vertices = {{0, 0, {}, {}}, {1, 1, {}, {}}};
  const WeightedDigraph graph = make_weighted_digraph(lonely.vertices);
  SearchOptions options;
  options.record_trace = true;
  const auto none = shortest_path(graph, 0, 1, options);
  const std::string svg = draw_search_animation(graph, 0, 1, none, {}, "none").str();
  EXPECT_NE(svg.find("no path, 1 expanded"), std::string::npos);
  EXPECT_EQ(count(svg, "<circle class=\"expanded\""), 1u);
}

// An animation is about 1 kB a vertex: a graph past the limit is refused up front, naming it, and
// its still picture is drawn.
TEST(SearchAnimation, AGraphPastTheLimitIsRefusedAndItsStillPictureDrawn) {
  GraphFile chain;
  for (std::size_t v = 0; v <= max_animated_vertices; ++v) {
    const double x = static_cast<double>(v);
    chain.vertices.push_back({x, 0, {}, {}});
    if (v > 0) chain.vertices[v - 1].neighbors = {v}, chain.vertices[v - 1].neighbors_cost = {1.0};
  }
  const WeightedDigraph graph = make_weighted_digraph(chain.vertices);
  SearchOptions options;
  options.record_trace = true;
  const auto result = shortest_path(graph, 0, max_animated_vertices, options);
  ASSERT_TRUE(result.found);
  try {
    draw_search_animation(graph, 0, max_animated_vertices, result, {}, "chain");
    ADD_FAILURE() << "an animation of " << max_animated_vertices + 1 << " vertices was drawn";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("animations draw at most 20000 vertices"), std::string::npos) << e.what();
  }
  EXPECT_NE(draw_search(graph, 0, max_animated_vertices, result, {}, "chain").str().find("<svg"), std::string::npos);
}
