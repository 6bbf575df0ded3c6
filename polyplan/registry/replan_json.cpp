#include <polyplan/registry/replan_json.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace polyplan {
namespace {

using nlohmann::json;

json cost_json(const OctileLength& c) { return c == OctileLength::infinity() ? json(nullptr) : json(c.to_double()); }

// A drive's cost in cells (its grid's units may be fractions of a cell).
json cells_cost_json(const OctileLength& c, const GridConventions& grid) {
  return c == OctileLength::infinity() ? json(nullptr) : json(grid.in_cells(c));
}

json cells_json(const std::vector<GridPoint>& cells) {
  json out = json::array();
  for (const GridPoint& p : cells) out.push_back(grid_point_json(p));
  return out;
}

}  // namespace

json grid_point_json(GridPoint p) { return json::array({p.x, p.y}); }

json grid_conventions_json(const GridConventions& grid) {
  return {{"connectivity", grid.connectivity == Connectivity::full ? 8 : 4},
          {"corner_cutting", grid.corner_cutting},
          {"diagonal_cost", grid.diagonal_cost.text()}};
}

json replan_json(const ReplanResult& r, double sensor) {
  json steps = json::array();
  for (const ReplanStep& s : r.steps)
    steps.push_back({{"at", grid_point_json(s.at)},
                     {"cost_to_goal", cells_cost_json(s.cost_to_goal, r.grid)},
                     {"cost_to_goal_exact", r.grid.text(s.cost_to_goal)},
                     {"expanded", s.expanded},
                     {"changed_cells", s.changed_cells},
                     {"replanned", s.replanned}});
  json out{{"found", r.found},
           {"status", std::string(to_string(r.status))},
           {"algorithm", std::string(to_string(r.algorithm))},
           {"sensor_radius", sensor},
           {"traversed", cells_json(r.traversed)},
           {"traversed_cost", r.grid.in_cells(r.traversed_cost)},
           {"traversed_cost_exact", r.grid.text(r.traversed_cost)},
           {"grid", grid_conventions_json(r.grid)},
           {"known_map", r.known_map},
           {"moves", r.moves},
           {"replans", r.replans},
           {"expanded", r.expanded},
           {"generated", r.generated},
           {"heap_operations", r.heap_operations},
           {"seconds", r.seconds},
           {"last_plan", cells_json(r.last_plan)},
           {"steps", steps}};
  if (r.status == PlanStatus::no_path)
    out["why_not"] = "the goal is unreachable on what the robot knows after " + std::to_string(r.moves) + " moves";
  if (r.status == PlanStatus::limit)
    out["why_not"] = r.timed_out ? "the time limit ended the drive after " + std::to_string(r.moves) + " moves"
                                 : "the robot made its limit of " + std::to_string(r.moves) + " moves";
  return out;
}

json replan_begins_json(std::size_t replan, GridPoint at, std::size_t changed) {
  return {{"replan", replan}, {"at", grid_point_json(at)}, {"changed_cells", changed}};
}

json replan_pass_json(const ReplanTracePass& p) {
  json updated = json::array(), open = json::array();
  for (const auto& u : p.updated)
    updated.push_back(
        {{"cell", grid_point_json(u.at)}, {"g", cost_json(u.g)}, {"rhs", cost_json(u.rhs)}, {"list", u.action}});
  for (const auto& e : p.open)
    open.push_back({{"cell", grid_point_json(e.at)},
                    {"g", cost_json(e.g)},
                    {"rhs", cost_json(e.rhs)},
                    {"key", {cost_json(e.key_first), cost_json(e.key_second)}},
                    {"state", e.state}});
  return {{"replan", p.replan},
          {"pass", p.pass},
          {"popped", grid_point_json(p.popped)},
          {"key", {cost_json(p.key_first), cost_json(p.key_second)}},
          {"kind", p.kind},
          {"g_before", cost_json(p.g_before)},
          {"g_after", cost_json(p.g_after)},
          {"rhs", cost_json(p.rhs)},
          {"updated", updated},
          {"open", open}};
}

}  // namespace polyplan
