#include "cli/plan_output.hpp"

#include <cstdio>

namespace polyplan::cli {

nlohmann::json plan_json(const Plan& plan) {
  nlohmann::json path = nlohmann::json::array(), exact = nlohmann::json::array();
  for (const ExactPoint& p : plan.path) {
    path.push_back({to_double(p.x), to_double(p.y)});
    exact.push_back({to_string(p.x), to_string(p.y)});
  }
  return {{"found", plan.found},
          {"length", plan.found ? nlohmann::json(plan.length) : nlohmann::json(nullptr)},
          {"path", path},
          {"path_exact", exact},
          {"roadmap",
           {{"kind", plan.roadmap.kind},
            {"vertices", plan.roadmap.vertices},
            {"edges", plan.roadmap.edges},
            {"seconds", plan.roadmap.seconds}}},
          {"search",
           {{"algorithm", std::string(to_string(plan.algorithm))},
            {"expanded", plan.expanded},
            {"generated", plan.generated},
            {"path_edges", plan.path.empty() ? 0 : plan.path.size() - 1},
            {"seconds", plan.search_seconds}}},
          {"query_seconds", plan.query_seconds}};
}

void print_plan(std::ostream& out, const Query& query, const Plan& plan) {
  char line[256];
  if (plan.found)
    std::snprintf(line, sizeof line, "%s: length %.6f, %zu segment(s), %s expanded %zu of %zu generated, roadmap %zu vertices %zu edges",
                  query.name.c_str(), plan.length, plan.path.size() - 1, std::string(to_string(plan.algorithm)).c_str(),
                  plan.expanded, plan.generated, plan.roadmap.vertices, plan.roadmap.edges);
  else
    std::snprintf(line, sizeof line, "%s: no path (start and goal are not connected in the free space)", query.name.c_str());
  out << line << '\n';
}

}  // namespace polyplan::cli
