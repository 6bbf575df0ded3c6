#include <polyplan/experiment/ompl_benchmark_log.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <utility>
#include <variant>
#include <vector>

#ifndef POLYPLAN_VERSION
#define POLYPLAN_VERSION "0"
#endif

namespace polyplan {
namespace {

// OMPL 1.5's PlannerStatus::asString, in the order of its values: the "status" enum every OMPL log
// declares, so that polyplan's runs sit beside OMPL's in one database.
constexpr std::array<const char*, 9> ompl_statuses{"Unknown status",         "Invalid start", "Invalid goal",
                                                   "Unrecognized goal type", "Timeout",       "Approximate solution",
                                                   "Exact solution",         "Crash",         "Abort"};

int ompl_status(PlanStatus status) {
  switch (status) {
    case PlanStatus::solved: return 6;         // Exact solution
    case PlanStatus::limit: return 4;          // Timeout
    case PlanStatus::invalid_query: return 1;  // Invalid start (or goal: polyplan_status and why_not say which)
    default: return 8;                         // Abort: no_path, not_found, local_minimum
  }
}

int plan_status_index(PlanStatus status) {
  for (std::size_t i = 0; i < all_plan_statuses.size(); ++i)
    if (all_plan_statuses[i] == status) return static_cast<int>(i);
  return 0;
}

// A value for the database: 17 significant digits ("inf" and "nan" as the script expects them).
// SQLite, which turns the script's text into REALs, does not round every shorter text correctly
// (3.40 reads "2.913327" as 2.9133269999999998), but it reads 17 digits back as the same double, so
// the database holds exactly results.json's values.
std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// A number for people (the setup text): the shortest text that reads back as the same double.
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// Whitespace and line breaks as '_': a name the log holds as one word or one line.
std::string one_word(std::string text) {
  for (char& c : text)
    if (std::isspace(static_cast<unsigned char>(c))) c = '_';
  return text.empty() ? "NO_NAME" : text;
}

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// SQLite's keywords and the runs table's own columns: never a column of ours.
const std::set<std::string>& reserved_columns() {
  static const std::set<std::string> words{"abort",
                                           "action",
                                           "add",
                                           "after",
                                           "all",
                                           "alter",
                                           "always",
                                           "analyze",
                                           "and",
                                           "as",
                                           "asc",
                                           "attach",
                                           "autoincrement",
                                           "before",
                                           "begin",
                                           "between",
                                           "by",
                                           "cascade",
                                           "case",
                                           "cast",
                                           "check",
                                           "collate",
                                           "column",
                                           "commit",
                                           "conflict",
                                           "constraint",
                                           "create",
                                           "cross",
                                           "current",
                                           "current_date",
                                           "current_time",
                                           "current_timestamp",
                                           "database",
                                           "default",
                                           "deferrable",
                                           "deferred",
                                           "delete",
                                           "desc",
                                           "detach",
                                           "distinct",
                                           "do",
                                           "drop",
                                           "each",
                                           "else",
                                           "end",
                                           "escape",
                                           "except",
                                           "exclude",
                                           "exclusive",
                                           "exists",
                                           "explain",
                                           "fail",
                                           "filter",
                                           "first",
                                           "following",
                                           "for",
                                           "foreign",
                                           "from",
                                           "full",
                                           "generated",
                                           "glob",
                                           "group",
                                           "groups",
                                           "having",
                                           "if",
                                           "ignore",
                                           "immediate",
                                           "in",
                                           "index",
                                           "indexed",
                                           "initially",
                                           "inner",
                                           "insert",
                                           "instead",
                                           "intersect",
                                           "into",
                                           "is",
                                           "isnull",
                                           "join",
                                           "key",
                                           "last",
                                           "left",
                                           "like",
                                           "limit",
                                           "match",
                                           "materialized",
                                           "natural",
                                           "no",
                                           "not",
                                           "nothing",
                                           "notnull",
                                           "null",
                                           "nulls",
                                           "of",
                                           "offset",
                                           "on",
                                           "or",
                                           "order",
                                           "others",
                                           "outer",
                                           "over",
                                           "partition",
                                           "plan",
                                           "pragma",
                                           "preceding",
                                           "primary",
                                           "query",
                                           "raise",
                                           "range",
                                           "recursive",
                                           "references",
                                           "regexp",
                                           "reindex",
                                           "release",
                                           "rename",
                                           "replace",
                                           "restrict",
                                           "returning",
                                           "right",
                                           "rollback",
                                           "row",
                                           "rows",
                                           "savepoint",
                                           "select",
                                           "set",
                                           "table",
                                           "temp",
                                           "temporary",
                                           "then",
                                           "ties",
                                           "to",
                                           "transaction",
                                           "trigger",
                                           "unbounded",
                                           "union",
                                           "unique",
                                           "update",
                                           "using",
                                           "vacuum",
                                           "values",
                                           "view",
                                           "virtual",
                                           "when",
                                           "where",
                                           "window",
                                           "with",
                                           "without",
                                           "id",
                                           "experimentid",
                                           "plannerid",
                                           "runid"};
  return words;
}

// A property's words as the log writes them ("roadmap vertices"): letters, digits and '_' kept,
// everything else a separating space; the script joins the words with '_' into its column.
std::string property_words(const std::string& name) {
  std::string words;
  bool space = false;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      if (space && !words.empty()) words += ' ';
      words += c;
      space = false;
    } else {
      space = true;
    }
  }
  if (words.empty() || std::isdigit(static_cast<unsigned char>(words.front()))) words = "fact " + words;
  std::string column = words;
  for (char& c : column) c = c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (reserved_columns().count(column)) words += " value";
  return words;
}

struct Property {
  std::string line;  // "solution length REAL"
  std::string value;
};

// One run's properties by column: what polyplan measures, then the planner's numeric facts (a
// fact whose column is taken already is left out).
std::map<std::string, Property> run_properties(const ExperimentRun& run) {
  std::map<std::string, Property> properties;
  const auto put = [&](const std::string& name, const char* type, std::string value) {
    const std::string column = ompl_column_name(name);
    properties.emplace(column, Property{property_words(name) + " " + type, std::move(value)});
  };
  put("time", "REAL", number(run.seconds));
  put("setup time", "REAL", number(run.setup_seconds));
  put("solved", "BOOLEAN", run.solved ? "1" : "0");
  put("status", "ENUM", std::to_string(ompl_status(run.status)));
  put("polyplan status", "ENUM", std::to_string(plan_status_index(run.status)));
  put("seed", "INTEGER", std::to_string(run.seed));
  if (run.solved) {
    put("solution length", "REAL", number(run.length));
    put("first solution time", "REAL", number(run.first_solution_seconds()));
  }
  for (const auto& [name, value] : run.facts.entries()) {
    if (const auto* flag = std::get_if<bool>(&value)) put(name, "BOOLEAN", *flag ? "1" : "0");
    else if (const auto* count = std::get_if<std::int64_t>(&value)) put(name, "INTEGER", std::to_string(*count));
    else if (const auto* measure = std::get_if<double>(&value)) put(name, "REAL", number(*measure));
    // words (roadmap.kind, stopped_by) are results.json's: the log's values are numbers
  }
  return properties;
}

void write_header(std::ostream& out, const Experiment& e, const ExperimentResults& r) {
  out << "polyplan version " << POLYPLAN_VERSION << '\n';
  out << "Experiment " << one_word(e.name) << '\n';
  out << "0 experiment properties\n";
  out << "Running on " << one_word(r.host) << '\n';
  out << "Starting at " << one_word(r.started_at) << '\n';
  out << "<<<|\n";
  out << "polyplan benchmark " << one_line(e.source) << '\n';
  for (const ExperimentProblem& p : e.problems)
    out << "problem " << one_line(p.name) << ": " << one_line(p.file) << ", query " << one_line(p.query) << '\n';
  for (const ExperimentPlanner& p : e.planners) {
    out << "planner entry " << one_line(p.name) << ": " << one_line(p.planner);
    for (const auto& [key, value] : p.options) out << ' ' << one_line(key) << '=' << one_line(value);
    out << '\n';
  }
  out << "seeds:";
  for (std::uint64_t seed : e.seeds) out << ' ' << seed;
  out << "\ncost times:";
  for (double t : e.cost_times) out << ' ' << shortest(t);
  out << "\nthreads: " << r.threads << '\n';
  if (r.runs.size() < e.cells())
    out << "incomplete: " << e.cells() - r.runs.size() << " of " << e.cells() << " runs missing\n";
  out << "|>>>\n";
  out << e.seeds.front() << " is the random seed\n";
  out << number(e.time_limit) << " seconds per run\n";
  out << "0 MB per run\n";
  out << e.seeds.size() << " runs per planner\n";
  out << number(r.total_seconds) << " seconds spent to collect the data\n";
  out << "2 enum types\nstatus";
  for (const char* status : ompl_statuses) out << '|' << status;
  out << "\npolyplan_status";
  for (PlanStatus status : all_plan_statuses) out << '|' << to_string(status);  // in PlanStatus's order
  out << '\n';
}

// The runs of one planner entry on one problem, as OMPL writes a planner's.
void write_planner(std::ostream& out, const Experiment& e, std::size_t problem, std::size_t planner,
                   const std::vector<const ExperimentRun*>& runs) {
  const ExperimentProblem& p = e.problems[problem];
  const ExperimentPlanner& entry = e.planners[planner];
  out << ompl_planner_name(e, problem, planner) << '\n';
  std::map<std::string, std::string> common{
      {"planner", entry.planner}, {"problem", p.name}, {"file", p.file}, {"query", p.query}};
  for (const auto& [key, value] : entry.options) common[key] = value;
  out << common.size() << " common properties\n";
  for (const auto& [key, value] : common) out << one_line(key) << " = " << one_line(value) << '\n';

  std::vector<std::map<std::string, Property>> values;
  std::map<std::string, std::string> lines;  // column → its line, the first run's that has it
  for (const ExperimentRun* run : runs) {
    values.push_back(run_properties(*run));
    for (const auto& [column, property] : values.back()) lines.emplace(column, property.line);
  }
  std::vector<std::pair<std::string, std::string>> order;  // (line, column), sorted by line as OMPL sorts
  for (const auto& [column, line] : lines) order.emplace_back(line, column);
  std::sort(order.begin(), order.end());
  out << order.size() << " properties for each run\n";
  for (const auto& [line, column] : order) out << line << '\n';
  out << runs.size() << " runs\n";
  for (const auto& run : values) {
    for (const auto& [line, column] : order) {
      const auto found = run.find(column);
      if (found != run.end()) out << found->second.value;
      out << "; ";
    }
    out << '\n';
  }

  if (entry.anytime && !e.cost_times.empty()) {
    out << "2 progress properties for each run\nbest cost REAL\ntime REAL\n" << runs.size() << " runs\n";
    for (const ExperimentRun* run : runs) {
      for (double t : e.cost_times) out << number(run->cost_at(t)) << ',' << number(t) << ",;";
      out << '\n';
    }
  }
  out << ".\n";
}

}  // namespace

std::string ompl_planner_name(const Experiment& experiment, std::size_t problem, std::size_t planner) {
  return one_word(experiment.planners[planner].name + "@" + experiment.problems[problem].name);
}

std::string ompl_column_name(const std::string& name) {
  std::string column = property_words(name);
  for (char& c : column)
    if (c == ' ') c = '_';
  return column;
}

void write_ompl_benchmark_log(std::ostream& out, const Experiment& experiment, const ExperimentResults& results) {
  write_header(out, experiment, results);
  std::vector<std::vector<const ExperimentRun*>> runs(experiment.problems.size() * experiment.planners.size());
  for (const ExperimentRun& run : results.runs)
    runs[run.problem * experiment.planners.size() + run.planner].push_back(&run);
  out << runs.size() << " planners\n";
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem)
    for (std::size_t planner = 0; planner < experiment.planners.size(); ++planner)
      write_planner(out, experiment, problem, planner, runs[problem * experiment.planners.size() + planner]);
}

}  // namespace polyplan
