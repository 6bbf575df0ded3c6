// io/graph_reader: the course's graph-search homework's graph_vector files, the forms the seed's Python writes, and
// every bad graph with its one-line message naming the vertex.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/graph_reader.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace polyplan;

namespace {

// The InputError message for a bad graph, or "" when it was accepted.
std::string error_for(const std::string& text) {
  try {
    std::vector<std::string> warnings;
    parse_graph(text, "graph.json", &warnings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kTwoVertices =
    R"({"x": [0, 0], "neighbors": [1], "neighbors_cost": [1]}, {"x": [1, 0], "neighbors": [0], "neighbors_cost": [1]})";

}  // namespace

TEST(GraphReader, ReadsTheSeedsVertexList) {
  std::vector<std::string> warnings;
  const GraphFile graph = parse_graph(R"([
    {"x": [0, 0.5], "neighbors": [1, 2], "neighbors_cost": [1, 1.4142135623730951], "g": 0.0, "backpointer": null},
    {"x": [1, 0.5], "neighbors": [], "neighbors_cost": [], "g": 2.5, "backpointer": 0.0},
    {"x": [[0], [1.5]], "neighbors": [[0]], "neighbors_cost": [["1/3"]], "colour": "red"}
  ])",
                                      "graph.json", &warnings);
  EXPECT_EQ(graph.source, "graph.json");
  ASSERT_EQ(graph.vertices.size(), 3u);
  EXPECT_EQ(graph.vertices[0].x, 0);
  EXPECT_EQ(graph.vertices[0].y, 0.5);
  EXPECT_EQ(graph.vertices[0].neighbors, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(graph.vertices[0].neighbors_cost, (std::vector<double>{1, 1.4142135623730951}));
  EXPECT_TRUE(graph.vertices[1].neighbors.empty());
  // numpy's column vectors, written by tolist(): [[x], [y]] and [i] for i.
  EXPECT_EQ(graph.vertices[2].y, 1.5);
  EXPECT_EQ(graph.vertices[2].neighbors, (std::vector<std::size_t>{0}));
  EXPECT_EQ(graph.vertices[2].neighbors_cost, (std::vector<double>{1.0 / 3}));
  // g and backpointer are the seed's (ignored); an unknown field is a warning.
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "graph.json: vertices[2]: unknown field \"colour\" ignored");
}

// Python's json writes float("inf") and float("nan") as Infinity and NaN: leftovers in g and
// backpointer are ignored, a cost that is one is refused.
TEST(GraphReader, ReadsPythonsInfinityAndNaNAsNull) {
  std::vector<std::string> warnings;
  const GraphFile graph =
      parse_graph(R"([{"x": [0, 0], "neighbors": [], "neighbors_cost": [], "g": Infinity, "backpointer": NaN,
    "note": "NaN stays text"}])",
                  "graph.json", &warnings);
  EXPECT_EQ(graph.vertices.size(), 1u);
  EXPECT_EQ(warnings.size(), 1u);  // the note, its text untouched
  EXPECT_EQ(error_for(R"([{"x": [0, 0], "neighbors": [0], "neighbors_cost": [-Infinity]}])"),
            "graph.json: vertices[0].neighbors_cost[0]: not a number: null");
}

TEST(GraphReader, AcceptsAnObjectWithVertices) {
  const GraphFile graph = parse_graph("{\"vertices\": [" + kTwoVertices + "]}", "graph.json");
  ASSERT_EQ(graph.vertices.size(), 2u);
  EXPECT_EQ(graph.vertices[1].neighbors, (std::vector<std::size_t>{0}));
}

TEST(GraphReader, NamesTheVertexOfEveryBadGraph) {
  const struct {
    const char* what;
    std::string text;
    const char* message;
  } cases[] = {
      {"index out of range",
       R"([{"x": [0, 0], "neighbors": [1], "neighbors_cost": [1]}, {"x": [1, 0], "neighbors": [0, 9], )"
       R"("neighbors_cost": [1, 1]}])",
       "graph.json: vertices[1].neighbors[1]: index 9 outside [0, 2)"},
      {"negative index", R"([{"x": [0, 0], "neighbors": [-1], "neighbors_cost": [1]}])",
       "graph.json: vertices[0].neighbors[0]: index -1 outside [0, 1)"},
      {"fractional index", R"([{"x": [0, 0], "neighbors": [0.5], "neighbors_cost": [1]}])",
       "graph.json: vertices[0].neighbors[0]: index 0.5 is not an integer (0-based indices [0, 1))"},
      {"negative cost", "[" + kTwoVertices + R"(, {"x": [2, 0], "neighbors": [0], "neighbors_cost": [-0.5]}])",
       "graph.json: vertices[2].neighbors_cost[0]: negative cost -0.5 (costs must be >= 0)"},
      {"cost beyond the supported range", R"([{"x": [0, 0], "neighbors": [0], "neighbors_cost": ["1e400"]}])",
       "graph.json: vertices[0].neighbors_cost[0]: "},
      {"cost not a number", R"([{"x": [0, 0], "neighbors": [0], "neighbors_cost": [true]}])",
       "graph.json: vertices[0].neighbors_cost[0]: not a number: true"},
      {"lists of different lengths", R"([{"x": [0, 0], "neighbors": [0, 0], "neighbors_cost": [1]}])",
       "graph.json: vertices[0]: 2 neighbors but 1 neighbors_cost (one cost per neighbour)"},
      {"missing x", R"([{"neighbors": [], "neighbors_cost": []}])", "graph.json: vertices[0]: missing field \"x\""},
      {"missing neighbors", R"([{"x": [0, 0], "neighbors_cost": []}])",
       "graph.json: vertices[0]: missing field \"neighbors\""},
      {"missing costs", R"([{"x": [0, 0], "neighbors": []}])",
       "graph.json: vertices[0]: missing field \"neighbors_cost\""},
      {"x not a point", R"([{"x": [0, 0, 0], "neighbors": [], "neighbors_cost": []}])",
       "graph.json: vertices[0].x: expected a point [x, y], got [0,0,0]"},
      {"neighbors not a list", R"([{"x": [0, 0], "neighbors": 3, "neighbors_cost": []}])",
       "graph.json: vertices[0].neighbors: expected a list of vertex indices, got 3"},
      {"vertex not an object", R"([[0, 0]])", "graph.json: vertices[0]: expected a vertex"},
      {"no vertices", "[]", "graph.json: vertices: the graph has no vertices"},
      {"neither list nor object", "3", "graph.json: graph: expected a list of vertices"},
      {"object without vertices", "{}", "graph.json: graph: missing field \"vertices\""},
      {"not JSON", "[{", "graph.json: invalid JSON"},
  };
  for (const auto& c : cases) {
    const std::string message = error_for(c.text);
    EXPECT_EQ(message.rfind(c.message, 0), 0u) << c.what << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.what;
  }
}

TEST(GraphReader, NamesAFileThatCannotBeRead) {
  try {
    read_graph("/nonexistent/graph.json");
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/graph.json: cannot open file");
  }
}

TEST(GraphReader, ReadsTheShippedGraphs) {
  for (const char* name : {"small.json", "grid_medium.json"}) {
    std::vector<std::string> warnings;
    const GraphFile graph = read_graph(std::string(POLYPLAN_SOURCE_DIR) + "/data/graphs/" + name, &warnings);
    EXPECT_FALSE(graph.vertices.empty()) << name;
    EXPECT_TRUE(warnings.empty()) << name << ": " << warnings.front();
  }
}
