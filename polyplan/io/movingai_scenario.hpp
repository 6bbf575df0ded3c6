#pragma once
// MovingAI scenario files (.scen) and the Euclidean reference lengths that come with the
// benchmark data (`index,length` CSV, -1 for no path).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct ScenarioQuery {
  int bucket = 0;
  int map_width = 0, map_height = 0;  // the size of the map the query was made for
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;
  double octile_length = 0;  // the file's optimal 8-connected length (rounded as printed)
  std::string octile_text;   // as printed, to know its precision
  int line = 0;              // where it is in the file, for error messages
};

// Throws InputError naming the file and line on anything malformed (a field missing or left
// over, a length that is not wholly a finite number, more than limits::scenario_queries).
std::vector<ScenarioQuery> read_scenarios(const std::string& path);

// The same from text already in memory; `name` stands for the file in messages.
std::vector<ScenarioQuery> parse_scenarios(const std::string& text, const std::string& name);

// Throws InputError naming the scenario file and line of the first query written for another
// map size, or whose start or goal cell lies outside the map.
void check_scenarios_match(const std::vector<ScenarioQuery>& queries, int map_width, int map_height,
                           const std::string& map_file, const std::string& scenario_file);

// The reference lengths of a scenario file of `queries` queries: reference[i] is the length for
// its query i, nullopt where the file has none; -1 means "no path". An index at or beyond
// `queries`, a line that is not 'index,length' or a missing header is an InputError.
std::vector<std::optional<double>> read_reference_lengths(const std::string& path, std::size_t queries);

// The same from text already in memory; `name` stands for the file in messages.
std::vector<std::optional<double>> parse_reference_lengths(const std::string& text, const std::string& name,
                                                           std::size_t queries);

}  // namespace polyplan
