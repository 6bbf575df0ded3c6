#include <polyplan/registry/potential_json.hpp>

#include <nlohmann/json.hpp>

namespace polyplan {

nlohmann::json potential_json(const PotentialStudy& s) {
  nlohmann::json points = nlohmann::json::array();
  for (const CriticalPoint& p : s.found.points)
    points.push_back({{"at", {p.at.x, p.at.y}},
                      {"kind", p.kind},
                      {"eigenvalues", {p.eigenvalues.smaller, p.eigenvalues.larger}},
                      {"value", p.value},
                      {"gradient", p.gradient}});
  const PotentialParameters& p = s.parameters;
  return {{"goal", {s.goal.x, s.goal.y}},
          {"parameters",
           {{"zeta", p.attractive.zeta},
            {"d_star", p.attractive.d_star},
            {"eta", p.repulsive.eta},
            {"q_star", p.repulsive.q_star}}},
          {"box", {s.box.xmin, s.box.ymin, s.box.xmax, s.box.ymax}},
          {"cells_per_axis", s.box.cells_per_axis},
          {"candidates", s.found.candidates},
          {"critical_points", points}};
}

}  // namespace polyplan
