#include <polyplan/io/graph_reader.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/detail/exact_json.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <string>

namespace polyplan {
namespace {

using json = nlohmann::json;

class GraphFileReader : public detail::JsonFileReader {
 public:
  using JsonFileReader::JsonFileReader;

  // [v] stands for v: numpy's column vectors, written by tolist(), nest each number in a list.
  static const json& unwrapped(const json& v) { return v.is_array() && v.size() == 1 ? unwrapped(v[0]) : v; }

  // A number as the file wrote it (floating-point literals arrive as their text).
  static std::string text(const json& value) {
    const json& v = unwrapped(value);
    return detail::abbreviated_text(v.is_string() ? v.get<std::string>() : v.dump());
  }

  double number(const json& value, const std::string& object) const {
    const json& v = unwrapped(value);
    if (!v.is_number_integer() && !v.is_number_unsigned() && !v.is_string())
      fail(object, "not a number: " + abbreviated(value));
    const std::string literal = v.is_string() ? v.get<std::string>() : v.dump();
    std::string why;
    const auto exact = parse_rational(literal, &why);
    if (!exact) fail(object, why + ": " + abbreviated(value));
    const double rounded = to_double(*exact);
    if (!std::isfinite(rounded)) fail(object, "not a finite number: " + text(value));
    return rounded;
  }

  const json& list(const json& v, const std::string& object, const std::string& expected) const {
    if (!v.is_array()) fail(object, "expected " + expected + ", got " + abbreviated(v));
    return v;
  }

  void read_point(const json& value, const std::string& object, GraphVertex& vertex) const {
    const json& v = value.is_array() && value.size() == 1 ? value[0] : value;  // a row [[x, y]]
    if (!v.is_array() || v.size() != 2) fail(object, "expected a point [x, y], got " + abbreviated(v));
    vertex.x = number(v[0], object + "[0]");
    vertex.y = number(v[1], object + "[1]");
  }

  std::size_t index(const json& v, const std::string& object, std::size_t count) const {
    const double i = number(v, object);
    const std::string range = "[0, " + std::to_string(count) + ")";
    if (i != std::floor(i)) fail(object, "index " + text(v) + " is not an integer (0-based indices " + range + ")");
    if (i < 0 || i >= static_cast<double>(count)) fail(object, "index " + text(v) + " outside " + range);
    return static_cast<std::size_t>(i);
  }

  GraphVertex vertex(const json& v, const std::string& object, std::size_t count,
                     std::vector<std::string>& warnings) const {
    if (!v.is_object())
      fail(object,
           "expected a vertex {\"x\": [x, y], \"neighbors\": [...], \"neighbors_cost\": [...]}, got " + abbreviated(v));
    warn_unknown(v, object, {"x", "neighbors", "neighbors_cost", "g", "backpointer"}, &warnings);
    GraphVertex vertex;
    read_point(required(v, "x", object), object + ".x", vertex);
    const json& neighbors = list(required(v, "neighbors", object), object + ".neighbors", "a list of vertex indices");
    const json& costs = list(required(v, "neighbors_cost", object), object + ".neighbors_cost", "a list of costs");
    if (neighbors.size() != costs.size())
      fail(object, std::to_string(neighbors.size()) + " neighbors but " + std::to_string(costs.size()) +
                       " neighbors_cost (one cost per neighbour)");
    for (std::size_t k = 0; k < neighbors.size(); ++k) {
      vertex.neighbors.push_back(index(neighbors[k], object + ".neighbors[" + std::to_string(k) + "]", count));
      const std::string cost_object = object + ".neighbors_cost[" + std::to_string(k) + "]";
      const double cost = number(costs[k], cost_object);
      if (cost < 0) fail(cost_object, "negative cost " + text(costs[k]) + " (costs must be >= 0)");
      vertex.neighbors_cost.push_back(cost);
    }
    return vertex;
  }
};

// Python's json module writes float("nan") and float("inf") as NaN and Infinity, which JSON does not
// have: outside strings they become null, an error where a number is needed, and ignored in the
// seed's g and backpointer (a search's leftovers).
std::string with_python_specials_as_null(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    bool replaced = false;
    for (const char* word : {"-Infinity", "Infinity", "NaN"}) {
      const std::size_t n = std::char_traits<char>::length(word);
      if (text.compare(i, n, word) == 0) {
        out += "null";
        i += n - 1;
        replaced = true;
        break;
      }
    }
    if (!replaced) out += c;
  }
  return out;
}

const json& vertex_list(const GraphFileReader& r, const json& root, std::vector<std::string>& warnings) {
  if (root.is_object()) {
    r.warn_unknown(root, "graph", {"vertices"}, &warnings);
    return r.list(r.required(root, "vertices", "graph"), "vertices", "a list of vertices");
  }
  return r.list(root, "graph", "a list of vertices (or {\"vertices\": [...]})");
}

}  // namespace

GraphFile parse_graph(const std::string& text, const std::string& name, std::vector<std::string>* warnings) {
  const GraphFileReader r(name);
  const json root = r.parse(with_python_specials_as_null(text));
  std::vector<std::string> found_warnings;
  const json& vertices = vertex_list(r, root, found_warnings);
  if (vertices.empty()) r.fail("vertices", "the graph has no vertices");
  GraphFile graph;
  graph.source = name;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    graph.vertices.push_back(
        r.vertex(vertices[i], "vertices[" + std::to_string(i) + "]", vertices.size(), found_warnings));
  if (warnings) warnings->insert(warnings->end(), found_warnings.begin(), found_warnings.end());
  else
    for (const auto& w : found_warnings) std::cerr << "warning: " << w << '\n';
  return graph;
}

GraphFile read_graph(const std::string& path, std::vector<std::string>* warnings) {
  return parse_graph(detail::read_text_file(path), path, warnings);
}

}  // namespace polyplan
