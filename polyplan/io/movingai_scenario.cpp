#include <polyplan/io/movingai_scenario.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/io/detail/text_file.hpp>

#include <charconv>
#include <cmath>
#include <sstream>
#include <tuple>

namespace polyplan {
namespace {

// The whole of `text` as a finite double ("1x", "nan" and "1e999" are not lengths).
std::optional<double> whole_double(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::vector<ScenarioQuery> read_scenarios(const std::string& path) {
  return parse_scenarios(detail::read_text_file(path), path);
}

std::vector<ScenarioQuery> parse_scenarios(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  int line_number = 1;
  if (!std::getline(in, line) || line.rfind("version", 0) != 0)
    throw InputError(path + ": line 1: expected 'version 1' (a MovingAI scenario file)");
  std::vector<ScenarioQuery> queries;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ": line " + std::to_string(line_number) + ": ";
    if (queries.size() == limits::scenario_queries)
      throw InputError(where + "more than the supported " + std::to_string(limits::scenario_queries) + " queries");
    std::istringstream fields(line);
    ScenarioQuery q;
    std::string map_name, rest;
    q.line = line_number;
    if (!(fields >> q.bucket >> map_name >> q.map_width >> q.map_height >> q.start_x >> q.start_y >> q.goal_x >>
          q.goal_y >> q.octile_text) ||
        (fields >> rest))
      throw InputError(where + "expected 'bucket map width height start_x start_y goal_x goal_y length'");
    const auto length = whole_double(q.octile_text);
    if (!length) throw InputError(where + "length is not a number: " + detail::abbreviated_text(q.octile_text));
    q.octile_length = *length;
    queries.push_back(q);
  }
  return queries;
}

void check_scenarios_match(const std::vector<ScenarioQuery>& queries, int map_width, int map_height,
                           const std::string& map_file, const std::string& scenario_file) {
  const std::string size = std::to_string(map_width) + "x" + std::to_string(map_height);
  for (const ScenarioQuery& q : queries) {
    const std::string where = scenario_file + ": line " + std::to_string(q.line) + ": ";
    if (q.map_width != map_width || q.map_height != map_height)
      throw InputError(where + "the query is for a " + std::to_string(q.map_width) + "x" +
                       std::to_string(q.map_height) + " map, " + map_file + " is " + size);
    for (const auto& [name, x, y] : {std::tuple{"start", q.start_x, q.start_y}, std::tuple{"goal", q.goal_x, q.goal_y}})
      if (x < 0 || y < 0 || x >= map_width || y >= map_height)
        throw InputError(where + name + " (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                         size + " map");
  }
}

std::vector<std::optional<double>> read_reference_lengths(const std::string& path, std::size_t queries) {
  return parse_reference_lengths(detail::read_text_file(path), path, queries);
}

std::vector<std::optional<double>> parse_reference_lengths(const std::string& text, const std::string& path,
                                                           std::size_t queries) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line.rfind("index,length", 0) != 0)
    throw InputError(path + ": line 1: expected the header 'index,length' (a reference-lengths file)");
  std::vector<std::optional<double>> lengths(queries);
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string where = path + ": line " + std::to_string(line_number) + ": ";
    const auto comma = line.find(',');
    // The index is read whole as an unsigned number ("-1" is not one) and checked against the
    // scenario file before anything is stored.
    std::size_t index = 0;
    const char* end = line.data() + (comma == std::string::npos ? line.size() : comma);
    const auto [stop, error] = std::from_chars(line.data(), end, index);
    const auto length = comma == std::string::npos ? std::nullopt : whole_double(line.substr(comma + 1));
    if (comma == std::string::npos || error != std::errc() || stop != end || !length)
      throw InputError(where + "expected 'index,length', got \"" + detail::abbreviated_text(line) + "\"");
    if (index >= queries)
      throw InputError(where + "index " + std::to_string(index) + " is beyond the scenario file's " +
                       std::to_string(queries) + " queries");
    lengths[index] = *length;
  }
  return lengths;
}

}  // namespace polyplan
