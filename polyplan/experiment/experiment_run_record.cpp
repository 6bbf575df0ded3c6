#include <polyplan/experiment/experiment_run_record.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>
#include <variant>

namespace polyplan {
namespace {

using nlohmann::json;

// A fact's kind as the record names it, in FactValue's order.
constexpr std::array<std::string_view, 7> fact_kinds{"flag", "count", "measure", "word", "point", "points", "cell"};

// A double as JSON: a number when finite (written to read back the same double), else "inf",
// "-inf" or "nan", which JSON has no number for.
json exact_number(double value) {
  if (std::isfinite(value)) return value;
  return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
}

json fact_json(const FactValue& value) {
  return std::visit(
      [](const auto& v) -> json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) return exact_number(v);
        else if constexpr (std::is_same_v<T, FactPoint>) return {exact_number(v[0]), exact_number(v[1])};
        else if constexpr (std::is_same_v<T, FactPoints>) {
          json points = json::array();
          for (const FactPoint& p : v) points.push_back({exact_number(p[0]), exact_number(p[1])});
          return points;
        } else return v;
      },
      value);
}

// Reads a record's fields, naming the record and the field in every complaint.
class RecordReader {
 public:
  RecordReader(const json& record, std::string where) : record_(record), where_(std::move(where)) {
    if (!record.is_object()) fail("record", "expected a JSON object");
  }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(where_ + ": " + field + ": " + what);
  }

  const json& field(const std::string& name) const {
    const auto at = record_.find(name);
    if (at == record_.end()) fail(name, "missing");
    return *at;
  }

  std::string text(const std::string& name) const {
    const json& value = field(name);
    if (!value.is_string()) fail(name, "expected text");
    return value.get<std::string>();
  }

  double number(const json& value, const std::string& name) const {
    if (value.is_number()) return value.get<double>();
    if (value == "inf") return std::numeric_limits<double>::infinity();
    if (value == "-inf") return -std::numeric_limits<double>::infinity();
    if (value == "nan") return std::numeric_limits<double>::quiet_NaN();
    fail(name, "expected a number");
  }
  double number(const std::string& name) const { return number(field(name), name); }

  FactPoint point(const json& value, const std::string& name) const {
    if (!value.is_array() || value.size() != 2) fail(name, "expected a point [x, y]");
    return {number(value[0], name), number(value[1], name)};
  }

  FactValue fact(const std::string& kind, const json& value, const std::string& name) const {
    if (kind == "flag" && value.is_boolean()) return value.get<bool>();
    if (kind == "count" && value.is_number_integer()) return value.get<std::int64_t>();
    if (kind == "measure") return number(value, name);
    if (kind == "word" && value.is_string()) return value.get<std::string>();
    if (kind == "point") return point(value, name);
    if (kind == "cell" && value.is_array() && value.size() == 2 && value[0].is_number_integer() &&
        value[1].is_number_integer())
      return FactCell{value[0].get<std::int64_t>(), value[1].get<std::int64_t>()};
    if (kind == "points" && value.is_array()) {
      FactPoints points;
      for (const json& p : value) points.push_back(point(p, name));
      return points;
    }
    fail(name, "expected a " + kind + ", got " + value.dump());
  }

 private:
  const json& record_;
  std::string where_;
};

std::size_t index_named(const RecordReader& r, const std::string& field, const std::string& name,
                        const std::vector<std::string>& names) {
  const auto at = std::find(names.begin(), names.end(), name);
  if (at == names.end()) r.fail(field, "\"" + name + "\" is not one of the experiment's");
  return static_cast<std::size_t>(at - names.begin());
}

template <class Item>
std::vector<std::string> names_of(const std::vector<Item>& items) {
  std::vector<std::string> names;
  for (const Item& item : items) names.push_back(item.name);
  return names;
}

PlanStatus status_named(const RecordReader& r, const std::string& word) {
  for (PlanStatus status : all_plan_statuses)
    if (to_string(status) == word) return status;
  r.fail("status", "\"" + word + "\" is not a status");
}

Facts facts_of(const RecordReader& r, const json& facts) {
  if (!facts.is_array()) r.fail("facts", "expected a list of [name, kind, value]");
  Facts out;
  for (const json& fact : facts) {
    if (!fact.is_array() || fact.size() != 3 || !fact[0].is_string() || !fact[1].is_string())
      r.fail("facts", "expected [name, kind, value], got " + fact.dump());
    const std::string name = fact[0].get<std::string>();
    const FactValue value = r.fact(fact[1].get<std::string>(), fact[2], "facts." + name);
    std::visit([&](const auto& v) { out.set(FactKey<std::decay_t<decltype(v)>>{name}, v); }, value);
  }
  return out;
}

std::size_t cell_of(const Experiment& e, const ExperimentRun& run) {
  const std::size_t seed =
      static_cast<std::size_t>(std::find(e.seeds.begin(), e.seeds.end(), run.seed) - e.seeds.begin());
  return (run.problem * e.planners.size() + run.planner) * e.seeds.size() + seed;
}

}  // namespace

json run_record(const ExperimentRun& run, const std::string& problem, const std::string& planner) {
  json improvements = json::array(), facts = json::array();
  for (const SolutionImprovement& i : run.improvements) improvements.push_back({i.seconds, i.length});
  for (const auto& [name, value] : run.facts.entries())
    facts.push_back({name, fact_kinds[value.index()], fact_json(value)});
  return {{"problem", problem},
          {"planner", planner},
          {"seed", run.seed},
          {"status", to_string(run.status)},
          {"solved", run.solved},
          {"why_not", run.why_not},
          {"seconds", run.seconds},
          {"setup_seconds", run.setup_seconds},
          {"length", exact_number(run.length)},
          {"improvements", improvements},
          {"facts", facts}};
}

ExperimentRun run_from_record(const Experiment& experiment, const json& record, const std::string& where) {
  const RecordReader r(record, where);
  ExperimentRun run;
  run.problem = index_named(r, "problem", r.text("problem"), names_of(experiment.problems));
  run.planner = index_named(r, "planner", r.text("planner"), names_of(experiment.planners));
  const json& seed = r.field("seed");
  if (!seed.is_number_integer() || (!seed.is_number_unsigned() && seed.get<std::int64_t>() < 0))
    r.fail("seed", "expected a whole number >= 0");
  run.seed = seed.get<std::uint64_t>();
  if (std::find(experiment.seeds.begin(), experiment.seeds.end(), run.seed) == experiment.seeds.end())
    r.fail("seed", std::to_string(run.seed) + " is not one of the experiment's seeds");
  run.status = status_named(r, r.text("status"));
  const json& solved = r.field("solved");
  if (!solved.is_boolean()) r.fail("solved", "expected true or false");
  run.solved = solved.get<bool>();
  run.why_not = r.text("why_not");
  run.seconds = r.number("seconds");
  run.setup_seconds = r.number("setup_seconds");
  run.length = r.number("length");
  const json& improvements = r.field("improvements");
  if (!improvements.is_array()) r.fail("improvements", "expected a list of [seconds, length]");
  for (const json& i : improvements) {
    const FactPoint pair = r.point(i, "improvements");
    run.improvements.push_back({pair[0], pair[1]});
  }
  run.facts = facts_of(r, r.field("facts"));
  return run;
}

std::vector<ExperimentRun> runs_in_cell_order(const Experiment& experiment, std::vector<ExperimentRun> runs) {
  std::stable_sort(runs.begin(), runs.end(), [&](const ExperimentRun& a, const ExperimentRun& b) {
    return cell_of(experiment, a) < cell_of(experiment, b);
  });
  runs.erase(std::unique(runs.begin(), runs.end(),
                         [&](const ExperimentRun& a, const ExperimentRun& b) {
                           return cell_of(experiment, a) == cell_of(experiment, b);
                         }),
             runs.end());
  return runs;
}

}  // namespace polyplan
