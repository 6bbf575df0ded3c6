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

nlohmann::json steering_words_json(const SteeringWords& words) {
  nlohmann::json listed = nlohmann::json::array();
  for (std::size_t i = 0; i < words.words.size(); ++i) {
    const SteeringWord& w = words.words[i];
    listed.push_back({{"name", w.name},
                      {"length", w.length ? nlohmann::json(*w.length) : nlohmann::json(nullptr)},
                      {"shortest", i == words.shortest}});
  }
  return listed;
}

std::string steering_words_text(const SteeringWords& words) {
  std::string text;
  for (std::size_t i = 0; i < words.words.size(); ++i) {
    const SteeringWord& w = words.words[i];
    char line[96];
    if (w.length)
      std::snprintf(line, sizeof line, "  %-12s %.6g%s\n", w.name.c_str(), *w.length,
                    i == words.shortest ? "  shortest" : "");
    else std::snprintf(line, sizeof line, "  %-12s infeasible\n", w.name.c_str());
    text += line;
  }
  return text;
}

std::string steering_summary(const std::string& model, const SteeringPath& path) {
  char length[32];
  std::snprintf(length, sizeof length, "%.6g", path.length());
  return model + " " + (path.word.empty() ? "(no motion)" : path.word) + ": length " + length;
}

}  // namespace polyplan
