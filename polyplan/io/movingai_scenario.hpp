#pragma once
// MovingAI scenario files (.scen) and the Euclidean reference lengths that come with the
// benchmark data (`index,length` CSV, -1 for no path).
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct ScenarioQuery {
  int bucket = 0;
  int map_width = 0, map_height = 0;  // the size of the map the query was made for
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;
  double octile_length = 0;     // the file's optimal 8-connected length (rounded as printed)
  std::string octile_text;      // as printed, to know its precision
  int line = 0;                 // where it is in the file, for error messages
};

// Throws InputError naming the file and line on anything malformed.
std::vector<ScenarioQuery> read_scenarios(const std::string& path);

// reference[i] is the length for scenario line i, nullopt where the file has none; -1 means
// "no path".
std::vector<std::optional<double>> read_reference_lengths(const std::string& path);

}  // namespace polyplan
