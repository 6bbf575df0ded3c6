#pragma once
// How `plan` and `arm` print reports: plan/plan_json.hpp's object per query (an object for
// one query, an array for several), and for people one line per query.
#include <polyplan/plan/plan_report.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace polyplan::cli {

// "NAME: length 118.944400, 5 segment(s), astar expanded 9 of 26 generated, roadmap 58 vertices
// 108 edges" (an arm's path to a goal point adds ", ends at IK solution 2 of 4 (goal.reached 1), the
// hand 2.2e-16 from the goal point"), from the shared facts (plan/plan_report.hpp) that the report has; or
// "NAME: no path (WHY)". `steps` names what lies between path entries ("segment", "motion").
template <class Configuration>
std::string report_line(const std::string& query, const PlanReport<Configuration>& report, const std::string& unit,
                        const std::string& steps);

// One answer per query: the object itself for one, an array for several.
nlohmann::json one_or_array(nlohmann::json answers);

}  // namespace polyplan::cli
