#include <polyplan/grids/movingai_grid.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/search/graph_search.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <tuple>

namespace polyplan {
namespace {

std::string cell_text(int x, int y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

}  // namespace

GridGraph movingai_grid(const GridMap& map, const GridConventions& conventions) {
  std::vector<std::uint8_t> free(map.blocked.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = !map.blocked[i];
  GridGraph graph({{map.width, AxisKind::bounded, 1.0}, {map.height, AxisKind::bounded, 1.0}}, conventions.connectivity,
                  StepCost::euclidean, std::move(free));
  set_diagonals(graph, conventions);
  return graph;
}

void check_scenarios_fit(const GridMap& map, const std::vector<ScenarioQuery>& queries,
                         const std::string& scenario_file) {
  check_scenarios_match(queries, map.width, map.height, map.source, scenario_file);
  for (const ScenarioQuery& q : queries) {
    const std::string where = scenario_file + ": line " + std::to_string(q.line) + ": ";
    for (const auto& [name, x, y] : {std::tuple{"start", q.start_x, q.start_y}, std::tuple{"goal", q.goal_x, q.goal_y}})
      if (map.is_blocked(x, y))
        throw InputError(where + name + " " + cell_text(x, y) + " is a blocked cell of " + map.source);
  }
}

double half_unit_in_last_place(const std::string& text) {
  // The digits after the decimal point, up to an exponent; the exponent shifts the last place.
  const std::size_t exponent_at = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, exponent_at);
  const std::size_t point = mantissa.find('.');
  const long decimals = point == std::string::npos ? 0 : static_cast<long>(mantissa.size() - point - 1);
  const long exponent = exponent_at == std::string::npos ? 0 : std::strtol(text.c_str() + exponent_at + 1, nullptr, 10);
  return 0.5 * std::pow(10.0, static_cast<double>(exponent - decimals));
}

OctileExpectation octile_expectation(const ScenarioQuery& q) {
  const bool same_cell = q.start_x == q.goal_x && q.start_y == q.goal_y;
  const bool found = !(q.octile_length < 0 || (q.octile_length == 0 && !same_cell));
  const double single_precision = std::abs(q.octile_length) * 0x1p-24;
  return {found, found ? q.octile_length : 0.0, half_unit_in_last_place(q.octile_text) + single_precision};
}

bool matches(const OctileExpectation& expected, bool found, double length) {
  if (found != expected.found) return false;
  // The slack covers only the rounding of summing 1s and sqrt(2)s in another order.
  return !found || std::abs(length - expected.length) <= expected.tolerance + 1e-12 * std::max(1.0, expected.length);
}

MovingAiGridSearch::MovingAiGridSearch(const GridMap& map, const GridConventions& conventions)
    : graph_(movingai_grid(map, conventions)) {}

SearchResult<GridCell> MovingAiGridSearch::search(const ScenarioQuery& q, const SearchOptions& options) {
  const auto free_cell = [&](const char* name, int x, int y) {
    const GridCoordinate at[2] = {x, y};
    if (x < 0 || y < 0 || x >= graph_.axis(0).cells || y >= graph_.axis(1).cells || !graph_.is_free(graph_.cell(at)))
      throw std::invalid_argument(std::string("MovingAiGridSearch: the ") + name + " " + cell_text(x, y) +
                                  " is not a free cell of the map");
    return graph_.cell(at);
  };
  const GridCell start = free_cell("start", q.start_x, q.start_y), goal = free_cell("goal", q.goal_x, q.goal_y);
  return shortest_path(graph_, start, goal, options, GridDistanceTo(graph_, goal, square_grid_metric(graph_)),
                       GridMoveCost{&graph_}, workspace_);
}

}  // namespace polyplan
