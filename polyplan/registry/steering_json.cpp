#include <polyplan/registry/steering_json.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace polyplan {

nlohmann::json steering_json(const SteeringPath& path) {
  nlohmann::json segments = nlohmann::json::array();
  for (const SteeringSegment& s : path.segments)
    segments.push_back({{"steer", std::string(1, static_cast<char>(s.steer))}, {"gear", s.gear}, {"length", s.length}});
  return {{"length", path.length()}, {"word", path.word}, {"segments", segments}};
}

std::string steering_summary(const std::string& model, const SteeringPath& path) {
  char length[32];
  std::snprintf(length, sizeof length, "%.6g", path.length());
  return model + " " + (path.word.empty() ? "(no motion)" : path.word) + ": length " + length;
}

}  // namespace polyplan
