#include <polyplan/experiment/experiment_file.hpp>

#include <polyplan/experiment/experiment_problem.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/detail/text_file.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace polyplan {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Reads one experiment file; each error names the file and the object.
class ExperimentReader {
 public:
  ExperimentReader(std::string name, fs::path folder) : file_(std::move(name)), folder_(std::move(folder)) {}

  [[noreturn]] void fail(const std::string& object, const std::string& what) const {
    throw InputError(file_ + ": " + object + ": " + what);
  }

  Experiment read(const json& root) {
    if (!root.is_object()) fail("experiment", "expected a JSON object with problems, planners, seeds and time_limit");
    const std::set<std::string> keys{"name", "problems", "planners", "seeds", "time_limit", "cost_times"};
    for (const auto& [key, value] : root.items())
      if (!keys.count(key))
        fail(key, "unknown key (an experiment has name, problems, planners, seeds, time_limit, cost_times)");
    Experiment e;
    e.source = file_;
    e.name = root.contains("name") ? text(root["name"], "name") : fs::path(file_).stem().string();
    e.time_limit = positive(required(root, "time_limit"), "time_limit");
    e.seeds = seeds(required(root, "seeds"));
    e.cost_times =
        root.contains("cost_times") ? cost_times(root["cost_times"], e.time_limit) : even_steps(e.time_limit);
    if (e.cost_times.front() <= 0)  // 5e-324 s split in 20 rounds to 0
      fail("time_limit",
           "too small to split into cost times a double holds apart: " + detail::show_number(e.time_limit));
    const json& problems = non_empty_array(required(root, "problems"), "problems");
    for (std::size_t i = 0; i < problems.size(); ++i)
      e.problems.push_back(problem(problems[i], "problems[" + std::to_string(i) + "]"));
    const json& planners = non_empty_array(required(root, "planners"), "planners");
    for (std::size_t i = 0; i < planners.size(); ++i)
      e.planners.push_back(planner(planners[i], "planners[" + std::to_string(i) + "]"));
    unique_names(e);
    check_planners_on_problems(e);
    return e;
  }

 private:
  const json& required(const json& object, const std::string& key, const std::string& where = "") const {
    if (!object.contains(key)) fail(where.empty() ? key : where + "." + key, "missing");
    return object[key];
  }
  std::string text(const json& value, const std::string& object) const {
    if (!value.is_string() || value.get<std::string>().empty()) fail(object, "expected a non-empty string");
    return value.get<std::string>();
  }
  double positive(const json& value, const std::string& object) const {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() <= 0)
      fail(object, "expected a positive number of seconds");
    return value.get<double>();
  }
  const json& non_empty_array(const json& value, const std::string& object) const {
    if (!value.is_array() || value.empty()) fail(object, "expected a non-empty array");
    return value;
  }

  std::vector<std::uint64_t> seeds(const json& value) const {
    std::vector<std::uint64_t> out;
    for (std::size_t i = 0; i < non_empty_array(value, "seeds").size(); ++i) {
      const std::string object = "seeds[" + std::to_string(i) + "]";
      if (!value[i].is_number_unsigned()) fail(object, "expected a whole number >= 0");
      const std::uint64_t seed = value[i].get<std::uint64_t>();
      // A seed names its run (a resumed experiment's records, a log's rows): two runs cannot share one.
      const auto earlier = std::find(out.begin(), out.end(), seed);
      if (earlier != out.end())
        fail(object, std::to_string(seed) + " repeats seeds[" + std::to_string(earlier - out.begin()) +
                         "] (a seed's run is the same run)");
      out.push_back(seed);
    }
    return out;
  }

  std::vector<double> cost_times(const json& value, double time_limit) const {
    std::vector<double> out;
    for (std::size_t i = 0; i < non_empty_array(value, "cost_times").size(); ++i) {
      const std::string object = "cost_times[" + std::to_string(i) + "]";
      const double t = positive(value[i], object);
      if (t > time_limit)
        fail(object, "after the time limit (" + detail::show_number(t) + " > " + detail::show_number(time_limit) + ")");
      if (!out.empty() && t <= out.back()) fail(object, "the times must increase");
      out.push_back(t);
    }
    return out;
  }

  static std::vector<double> even_steps(double time_limit) {
    constexpr int steps = 20;
    std::vector<double> out;
    for (int i = 1; i <= steps; ++i) out.push_back(time_limit * i / steps);
    return out;
  }

  ExperimentProblem problem(const json& value, const std::string& object) {
    if (!value.is_object()) fail(object, "expected an object with name, file and query");
    for (const auto& [key, v] : value.items())
      if (key != "name" && key != "file" && key != "query" && key != "kind")
        fail(object + "." + key, "unknown key (a problem has name, file, query, kind)");
    ExperimentProblem p;
    p.name = text(required(value, "name", object), object + ".name");
    const std::string file = text(required(value, "file", object), object + ".file");
    // The file system would stop at a NUL and open another file than the one named.
    if (file.find('\0') != std::string::npos) fail(object + ".file", "a path with a NUL character");
    p.file = (fs::path(file).is_absolute() ? fs::path(file) : folder_ / file).lexically_normal().string();
    Problem loaded = [&] {
      try {
        std::vector<std::string> warnings;  // unknown fields of a problem file are not the experiment's concern
        return Problem::read(p.file, &warnings);
      } catch (const InputError& e) {
        fail(object + ".file", e.what());
      }
    }();
    p.kind = loaded.arm() ? ProblemKind::arm : ProblemKind::world;
    if (value.contains("kind")) check_kind(value["kind"], object, p.kind);
    p.query = query(value, object, loaded.query_names());
    loaded_.push_back(std::move(loaded));
    return p;
  }

  // A kind the experiment names is the file's own.
  void check_kind(const json& value, const std::string& object, ProblemKind kind) const {
    const std::string named = text(value, object + ".kind");
    if (named != "world" && named != "arm") fail(object + ".kind", "expected \"world\" or \"arm\"");
    const char* is = kind == ProblemKind::arm ? "arm" : "world";
    if (named != is)
      fail(object + ".kind",
           "\"" + named + "\", but the file is " + (kind == ProblemKind::arm ? "an arm file" : "a world file"));
  }

  std::string query(const json& value, const std::string& object, const std::vector<std::string>& names) const {
    std::string listed;
    for (const auto& n : names) listed += (listed.empty() ? "" : ", ") + n;
    if (names.empty()) fail(object + ".file", "the file has no query (no start/goal and no queries)");
    if (!value.contains("query")) return names.front();
    const json& q = value["query"];
    if (q.is_number_unsigned()) {
      if (q.get<std::size_t>() >= names.size())
        fail(object + ".query",
             "no query " + q.dump() + " (the file has " + std::to_string(names.size()) + ": " + listed + ")");
      return names[q.get<std::size_t>()];
    }
    const std::string name = text(q, object + ".query");
    if (std::find(names.begin(), names.end(), name) == names.end())
      fail(object + ".query", "no query named \"" + name + "\" (queries: " + listed + ")");
    return name;
  }

  ExperimentPlanner planner(const json& value, const std::string& object) const {
    if (!value.is_object()) fail(object, "expected an object with name, planner and options");
    for (const auto& [key, v] : value.items())
      if (key != "name" && key != "planner" && key != "options")
        fail(object + "." + key, "unknown key (a planner entry has name, planner, options)");
    ExperimentPlanner p;
    p.name = text(required(value, "name", object), object + ".name");
    p.planner = text(required(value, "planner", object), object + ".planner");
    if (!value.contains("options")) return p;
    const json& options = value["options"];
    if (!options.is_object()) fail(object + ".options", "expected an object of NAME: VALUE");
    for (const auto& [key, v] : options.items()) {
      const std::string where = object + ".options." + key;
      if (key == "seed") fail(where, "the experiment's seeds set it");
      if (key == "time") fail(where, "the experiment's time_limit sets it");
      p.options.emplace_back(key, option_text(v, where));
    }
    return p;
  }

  // An option's value as the command line would give it.
  std::string option_text(const json& value, const std::string& object) const {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_number_integer()) return value.dump();
    if (value.is_number()) return detail::show_number(value.get<double>());
    fail(object, "expected a number, text or true/false");
  }

  void unique_names(const Experiment& e) const {
    std::set<std::string> seen;
    for (std::size_t i = 0; i < e.problems.size(); ++i)
      if (!seen.insert(e.problems[i].name).second)
        fail("problems[" + std::to_string(i) + "].name", "\"" + e.problems[i].name + "\" names two problems");
    seen.clear();
    for (std::size_t i = 0; i < e.planners.size(); ++i)
      if (!seen.insert(e.planners[i].name).second)
        fail("planners[" + std::to_string(i) + "].name", "\"" + e.planners[i].name + "\" names two planner entries");
  }

  // Every planner entry is one the registry builds, with its options, for every problem.
  void check_planners_on_problems(Experiment& e) const {
    for (std::size_t i = 0; i < e.planners.size(); ++i) {
      ExperimentPlanner& p = e.planners[i];
      const std::string object = "planners[" + std::to_string(i) + "]";
      for (std::size_t j = 0; j < e.problems.size(); ++j) {
        const Problem& problem = loaded_[j];
        const PlannerListing* listing = nullptr;
        try {
          listing = &planner_for(p.planner, problem);
        } catch (const InputError& error) {
          fail(object + ".planner",
               "no planner \"" + p.planner + "\" plans problems[" + std::to_string(j) + "]: " + error.what());
        }
        const std::vector<OptionInfo>& known = listing->options;
        for (const auto& option : p.options) {
          const std::string& key = option.first;  // not a structured binding: clang 14 cannot capture one
          if (std::none_of(known.begin(), known.end(), [&](const OptionInfo& o) { return o.name == key; }))
            fail(object + ".options." + key,
                 "unknown option for " + p.planner + " (options: " + option_names(known) + ")");
        }
        try {
          // Building is what checks the values; a planner built on a problem costs little beside a run.
          make_planner(p.planner, problem, options_for_run(p.options, known, e.seeds.front(), e.time_limit));
        } catch (const InputError& error) {
          fail(object, std::string(error.what()) + " (on problems[" + std::to_string(j) + "])");
        }
        p.anytime = p.anytime || listing->anytime;
      }
    }
  }

  static std::string option_names(const std::vector<OptionInfo>& known) {
    std::string names;
    for (const OptionInfo& o : known)
      if (o.name != "seed" && o.name != "time") names += (names.empty() ? "" : ", ") + o.name;
    return names.empty() ? "none" : names;
  }

  std::string file_;
  fs::path folder_;
  std::vector<Problem> loaded_;  // problems[i]'s file, read once for the checks
};

}  // namespace

Experiment parse_experiment(const std::string& text, const std::string& name) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(name + ": not JSON: " + e.what());
  }
  return ExperimentReader(name, fs::path(name).parent_path()).read(root);
}

Experiment read_experiment(const std::string& path) { return parse_experiment(detail::read_text_file(path), path); }

}  // namespace polyplan
