#include <polyplan/registry/ik_json.hpp>

#include <nlohmann/json.hpp>

namespace polyplan {

nlohmann::json ik_json(const IkRequest& request, const IkStudy& study) {
  nlohmann::json solutions = nlohmann::json::array();
  for (std::size_t i = 0; i < study.answer.solutions.size(); ++i)
    solutions.push_back({{"angles", study.answer.solutions[i].angles},
                         {"error", study.answer.solutions[i].error},
                         {"free", bool(study.free[i])}});
  nlohmann::json out = {
      {"target", {request.target.x(), request.target.y()}}, {"found", study.answer.found}, {"solutions", solutions}};
  out["orientation"] = request.orientation_degrees ? nlohmann::json(*request.orientation_degrees) : nullptr;
  if (!study.answer.found) out["why_not"] = study.answer.why_not;
  return out;
}

}  // namespace polyplan
