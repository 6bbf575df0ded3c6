#include <polyplan/experiment/experiment_results.hpp>

#include <polyplan/experiment/experiment_statistics.hpp>
#include <polyplan/experiment/ompl_benchmark_log.hpp>
#include <polyplan/plan/plan_json.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ostream>
#include <variant>

namespace polyplan {
namespace {

using nlohmann::json;

json finite_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

}  // namespace

json experiment_json(const Experiment& e) {
  json problems = json::array(), planners = json::array();
  for (const ExperimentProblem& p : e.problems)
    problems.push_back({{"name", p.name},
                        {"file", p.file},
                        {"kind", p.kind == ProblemKind::arm ? "arm" : "world"},
                        {"query", p.query}});
  for (const ExperimentPlanner& p : e.planners) {
    json options = json::object();
    for (const auto& [key, value] : p.options) options[key] = value;
    planners.push_back({{"name", p.name}, {"planner", p.planner}, {"options", options}, {"anytime", p.anytime}});
  }
  return {{"name", e.name},      {"file", e.source},           {"time_limit", e.time_limit},
          {"seeds", e.seeds},    {"cost_times", e.cost_times}, {"problems", problems},
          {"planners", planners}};
}

namespace {

json run_json(const Experiment& e, const ExperimentRun& run) {
  json out{{"problem", e.problems[run.problem].name},
           {"planner", e.planners[run.planner].name},
           {"log_planner", ompl_planner_name(e, run.problem, run.planner)},
           {"seed", run.seed},
           {"solved", run.solved},
           {"status", std::string(to_string(run.status))},
           {"time", run.seconds},
           {"setup_time", run.setup_seconds},
           {"length", run.solved ? json(run.length) : json(nullptr)},
           {"first_solution_time", finite_or_null(run.first_solution_seconds())}};
  json improvements = json::array(), costs = json::array();
  for (const SolutionImprovement& i : run.improvements) improvements.push_back({i.seconds, i.length});
  for (double t : e.cost_times) costs.push_back(finite_or_null(run.cost_at(t)));
  out["improvements"] = improvements;
  out["cost_at"] = costs;
  if (!run.solved) out["why_not"] = run.why_not;
  out["facts"] = facts_json(run.facts);
  return out;
}

json summary_json(const ValueSummary& s) {
  return {{"mean", finite_or_null(s.mean)},     {"std", s.stddev},
          {"median", finite_or_null(s.median)}, {"q1", finite_or_null(s.q1)},
          {"q3", finite_or_null(s.q3)},         {"min", finite_or_null(s.min)},
          {"max", finite_or_null(s.max)}};
}

// CSV: a field with a comma, a quote or a line break in quotes, its quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_number(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

std::string csv_fact(const FactValue& value) {
  if (const auto* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
  if (const auto* count = std::get_if<std::int64_t>(&value)) return std::to_string(*count);
  if (const auto* measure = std::get_if<double>(&value)) return csv_number(*measure);
  if (const auto* word = std::get_if<std::string>(&value)) return csv_field(*word);
  return csv_field(std::visit([](const auto& v) { return json(v).dump(); }, value));  // a point's "[x,y]"
}

}  // namespace

json experiment_results_json(const Experiment& experiment, const ExperimentResults& results) {
  json runs = json::array();
  for (const ExperimentRun& run : results.runs) runs.push_back(run_json(experiment, run));
  json summary = json::array();
  const auto statistics = experiment_statistics(experiment, results);
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem)
    for (std::size_t planner = 0; planner < experiment.planners.size(); ++planner) {
      const CellStatistics& s = statistics[problem][planner];
      summary.push_back({{"problem", experiment.problems[problem].name},
                         {"planner", experiment.planners[planner].name},
                         {"log_planner", ompl_planner_name(experiment, problem, planner)},
                         {"runs", s.runs},
                         {"solved", s.solved},
                         {"success_rate", s.success_rate},
                         {"time", summary_json(s.time)},
                         {"length", summary_json(s.length)}});
    }
  return {{"experiment", experiment_json(experiment)},
          {"host", results.host},
          {"started_at", results.started_at},
          {"threads", results.threads},
          {"total_seconds", results.total_seconds},
          {"complete", results.runs.size() == experiment.cells()},
          {"missing_runs", experiment.cells() - results.runs.size()},
          {"log", "results.log"},
          {"runs", runs},
          {"summary", summary}};
}

void write_experiment_results_csv(std::ostream& out, const Experiment& experiment, const ExperimentResults& results) {
  std::vector<std::string> facts;  // every fact name, in the order first met
  for (const ExperimentRun& run : results.runs)
    for (const auto& [name, value] : run.facts.entries())
      if (std::find(facts.begin(), facts.end(), name) == facts.end()) facts.push_back(name);

  out << "problem,planner,log_planner,seed,solved,status,time,setup_time,length,first_solution_time";
  for (double t : experiment.cost_times) out << ",cost_at_" << csv_number(t);
  for (const std::string& name : facts) out << ',' << csv_field(name);
  out << ",why_not\n";
  for (const ExperimentRun& run : results.runs) {
    out << csv_field(experiment.problems[run.problem].name) << ',' << csv_field(experiment.planners[run.planner].name)
        << ',' << csv_field(ompl_planner_name(experiment, run.problem, run.planner)) << ',' << run.seed << ','
        << (run.solved ? "true" : "false") << ',' << to_string(run.status) << ',' << csv_number(run.seconds) << ','
        << csv_number(run.setup_seconds) << ',' << (run.solved ? csv_number(run.length) : "") << ','
        << csv_number(run.first_solution_seconds());
    for (double t : experiment.cost_times) out << ',' << csv_number(run.cost_at(t));
    for (const std::string& name : facts) {
      out << ',';
      if (const FactValue* value = run.facts.value_named(name)) out << csv_fact(*value);
    }
    out << ',' << (run.solved ? "" : csv_field(run.why_not)) << '\n';
  }
}

}  // namespace polyplan
