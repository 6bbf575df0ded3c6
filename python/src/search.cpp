// polyplan.search_graph: a search on the course's graph-search homework's graph_vector (polyplan search), its path,
// cost, counts and trace as a dict, and its picture.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/draw/search_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/graph_reader.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// A file's path, or the seed's list of dicts (written as JSON and read by the one reader, so that
// its checks and messages are the file's, the graph named "graph").
GraphFile graph_of(const py::object& graph) {
  if (py::isinstance<py::str>(graph) || py::hasattr(graph, "__fspath__"))
    return read_graph(path_of(graph, "search_graph: graph"));
  // Numpy fields and scalars, nesting and cycles as for a world given as a dict; floats stay floats.
  const py::object plain = py::module_::import("polyplan").attr("_json_value")(graph, "graph", false);
  return parse_graph(py::module_::import("json").attr("dumps")(plain).cast<std::string>(), "graph");
}

// A vertex index: any integer (numpy's among them), checked against the graph before it is narrowed.
DigraphVertexId vertex_of(const GraphFile& file, const py::object& index, const char* what) {
  if (!PyIndex_Check(index.ptr()) || is_boolean(index) || py::isinstance<py::array>(index))
    throw InputError(std::string(what) + ": expected a vertex index (an int), got " + type_name(index));
  const py::int_ value = py::reinterpret_steal<py::int_>(PyNumber_Index(index.ptr()));
  if (value < py::int_(0) || value >= py::int_(file.vertices.size())) {
    // Named by its bits past 64 of them: str() refuses an int of more than 4300 digits.
    const auto bits = value.attr("bit_length")().cast<long long>();
    const std::string shown =
        bits > 64 ? "(an integer of " + std::to_string(bits) + " bits)" : py::repr(value).cast<std::string>();
    throw InputError(std::string(what) + " " + shown + ": not a vertex of " + file.source + " (0-based indices [0, " +
                     std::to_string(file.vertices.size()) + "))");
  }
  return value.cast<DigraphVertexId>();
}

py::object optional_vertex(const std::optional<DigraphVertexId>& v) {
  return v ? py::object(py::int_(*v)) : py::object(py::none());
}

// Each vertex's g and backpointer when the search ended, read from the trace's last label of each
// (the costs summed along the backpointers, for every method): inf and None where the search never
// reached; the start's backpointer None. What search_graph(write_back=True) writes into the graph.
void add_labels(py::dict& d, const SearchTrace<DigraphVertexId>& trace, std::size_t vertices) {
  py::list g, backpointer;
  for (std::size_t v = 0; v < vertices; ++v) {
    g.append(py::float_(std::numeric_limits<double>::infinity()));
    backpointer.append(py::none());
  }
  for (const auto& label : trace.labels) {
    g[label.vertex] = py::float_(label.g);
    backpointer[label.vertex] = optional_vertex(label.backpointer);
  }
  d["g"] = g;
  d["backpointer"] = backpointer;
}

py::dict result_dict(const SearchResult<DigraphVertexId>& r, const WeightedDigraph& graph, DigraphVertexId start,
                     DigraphVertexId goal, const std::string& method) {
  py::dict d;
  d["found"] = r.found;
  d["method"] = method;
  d["path"] = r.path;
  d["cost"] = r.found ? py::object(py::float_(r.cost)) : py::object(py::none());
  d["expanded"] = r.expanded;
  d["generated"] = r.generated;
  d["expansion_order"] = r.expanded_order;
  py::list trace;
  for (const auto& e : r.trace.expansions) {
    py::dict line;
    line["step"] = e.step;
    line["vertex"] = e.vertex;
    line["g"] = e.g;
    line["h"] = e.h;
    line["f"] = e.f;
    line["backpointer"] = optional_vertex(e.backpointer);
    line["open"] = e.open;
    trace.append(line);
  }
  d["trace"] = trace;
  add_labels(d, r.trace, num_vertices(graph));
  d["svg"] = draw_search(graph, start, goal, r, {}, "polyplan.search_graph").str();
  d["animation"] =
      num_vertices(graph) > max_animated_vertices
          ? py::object(py::none())
          : py::object(py::str(draw_search_animation(graph, start, goal, r, {}, "polyplan.search_graph").str()));
  return d;
}

// The method's name: search_result.hpp's, "uniform-cost" (Dijkstra by the course's name), or
// "bidirectional" (nullopt: bidirectional Dijkstra, which is no SearchOptions algorithm).
std::optional<Search> method_of(const std::string& method) {
  if (method == "bidirectional") return std::nullopt;
  for (const auto& [name, algorithm] : course_search_names)
    if (method == name) return algorithm;
  if (const auto algorithm = search_from_string(method)) return algorithm;
  throw InputError("method " + method +
                   ": unknown method (astar, dijkstra, uniform-cost, bfs, dfs, greedy, wastar, bidirectional)");
}

}  // namespace

void bind_search(py::module_& m) {
  m.def(
      "search_graph",
      [](const py::object& graph, const py::object& start_index, const py::object& goal_index,
         const py::object& method_given, const py::object& weight_given, const py::object& reopen_given) {
        const std::string method = text_of(method_given, "method");
        const double weight = finite_number(weight_given, "weight");
        const bool reopen = flag_of(reopen_given, "reopen");
        const GraphFile file = graph_of(graph);
        const DigraphVertexId start = vertex_of(file, start_index, "start"), goal = vertex_of(file, goal_index, "goal");
        const auto algorithm = method_of(method);
        const WeightedDigraph g = make_weighted_digraph(file.vertices);
        if (!algorithm) {
          // Two searches, from the start and from the goal: no one g and backpointer per vertex.
          py::dict d = result_dict(bidirectional_shortest_path(g, start, goal), g, start, goal, "bidirectional");
          d["g"] = py::none();
          d["backpointer"] = py::none();
          return d;
        }
        SearchOptions options;
        options.algorithm = *algorithm;
        if (options.algorithm == Search::wastar && !(std::isfinite(weight) && weight >= 1))
          throw InputError("weight " + std::to_string(weight) + ": weighted A* needs a finite weight >= 1");
        options.weight = weight;
        options.reopen = reopen;
        options.record_expanded = options.record_trace = options.ties_first_discovered = true;
        return result_dict(shortest_path(g, start, goal, options), g, start, goal, std::string(to_string(*algorithm)));
      },
      py::arg("graph"), py::arg("start"), py::arg("goal"), py::arg("method") = "astar", py::arg("weight") = 1.5,
      py::arg("reopen") = false,
      R"(The search of polyplan.search_graph (whose docstring says it all) without frames and write_back:
the dict it returns, g and backpointer per vertex among its entries.)");
}

}  // namespace polyplan::python
