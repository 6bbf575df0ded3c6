#include "cli/report_output.hpp"

#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/rotation.hpp>

#include <cstdio>

namespace polyplan::cli {

template <class Configuration>
std::string report_line(const std::string& query, const PlanReport<Configuration>& report, const std::string& unit,
                        const std::string& steps) {
  if (!report.found) return query + ": no path (" + report.why_not + ")";
  char text[128];
  std::snprintf(text, sizeof text, "%s: length %.6f%s, %zu %s(s)", query.c_str(), report.length, unit.c_str(),
                report.path.size() - 1, steps.c_str());
  std::string line = text;
  const Facts& facts = report.facts;
  if (facts.contains("search.algorithm") && facts.contains("search.expanded") && facts.contains("search.generated"))
    line += ", " + facts.text("search.algorithm") + " expanded " + std::to_string(facts.count("search.expanded")) + " of " +
            std::to_string(facts.count("search.generated")) + " generated";
  if (facts.contains("roadmap.vertices") && facts.contains("roadmap.edges"))
    line += ", roadmap " + std::to_string(facts.count("roadmap.vertices")) + " vertices " +
            std::to_string(facts.count("roadmap.edges")) + " edges";
  if (facts.contains("gear_changes")) line += ", " + std::to_string(facts.count("gear_changes")) + " gear change(s)";
  if (facts.contains("goal.error") && facts.contains("goal.reached") && facts.contains("goal.candidates")) {
    char goal[160];
    std::snprintf(goal, sizeof goal, ", ends at IK solution %lld of %lld (goal.reached %lld), the hand %.2g from the goal point",
                  static_cast<long long>(facts.count("goal.reached") + 1), static_cast<long long>(facts.count("goal.candidates")),
                  static_cast<long long>(facts.count("goal.reached")), facts.number("goal.error"));
    line += goal;
  }
  if (facts.contains("note")) line += "; " + facts.text("note");
  return line;
}

template std::string report_line(const std::string&, const PlanReport<ExactPoint>&, const std::string&, const std::string&);
template std::string report_line(const std::string&, const PlanReport<JointAngles>&, const std::string&, const std::string&);
template std::string report_line(const std::string&, const PlanReport<Pose>&, const std::string&, const std::string&);
template std::string report_line(const std::string&, const PlanReport<CarState>&, const std::string&, const std::string&);

nlohmann::json one_or_array(nlohmann::json answers) { return answers.size() == 1 ? answers[0] : answers; }

}  // namespace polyplan::cli
