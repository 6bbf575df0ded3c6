#include <polyplan/io/movingai_scenario.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <fstream>
#include <sstream>

namespace polyplan {

std::vector<ScenarioQuery> read_scenarios(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file");
  std::string line;
  int line_number = 1;
  if (!std::getline(in, line) || line.rfind("version", 0) != 0)
    throw InputError(path + ": line 1: expected 'version 1' (a MovingAI scenario file)");
  std::vector<ScenarioQuery> queries;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    ScenarioQuery q;
    std::string map_name;
    q.line = line_number;
    if (!(fields >> q.bucket >> map_name >> q.map_width >> q.map_height >> q.start_x >> q.start_y >> q.goal_x >> q.goal_y >> q.octile_text))
      throw InputError(path + ": line " + std::to_string(line_number) +
                       ": expected 'bucket map width height start_x start_y goal_x goal_y length'");
    try {
      q.octile_length = std::stod(q.octile_text);
    } catch (const std::exception&) {
      throw InputError(path + ": line " + std::to_string(line_number) + ": length is not a number: " + q.octile_text);
    }
    queries.push_back(q);
  }
  return queries;
}

std::vector<std::optional<double>> read_reference_lengths(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file");
  std::string line;
  std::getline(in, line);  // header: index,length
  std::vector<std::optional<double>> lengths;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    const auto comma = line.find(',');
    if (comma == std::string::npos) continue;
    try {
      const std::size_t index = std::stoul(line.substr(0, comma));
      if (index >= lengths.size()) lengths.resize(index + 1);
      lengths[index] = std::stod(line.substr(comma + 1));
    } catch (const std::exception&) {
      throw InputError(path + ": line " + std::to_string(line_number) + ": expected 'index,length'");
    }
  }
  return lengths;
}

}  // namespace polyplan
