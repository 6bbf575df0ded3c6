#include <polyplan/experiment/experiment_problem.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace polyplan {
namespace {

// A world's C-space is built once for its translating planners; rotating robots and cars plan
// on the world itself.
struct WorldProblem {
  std::unique_ptr<World> world;
  std::unique_ptr<CSpace> cspace;  // null for a car
};

template <class Queries>
const auto& query_named(const Queries& queries, const std::string& name, const std::string& file) {
  for (const auto& q : queries)
    if (q.name == name) return q;
  throw std::logic_error(file + ": no query named " + name + " (the experiment's reader checks it)");
}

template <class Configuration>
void record(PlanReport<Configuration>&& report, ExperimentRun& run) {
  run.status = report.status;
  run.solved = report.found;
  run.why_not = std::move(report.why_not);
  run.length = report.found ? report.length : 0;
  run.facts = std::move(report.facts);
  run.improvements.clear();
  if (!report.found) return;
  run.improvements = std::move(report.improvements);
  // A planner that answers once has its one solution when its query ends.
  if (run.improvements.empty()) run.improvements.push_back({run.seconds, run.length});
}

template <class Space>
void run_in(const typename Space::Problem& problem, const typename Space::Query& query, const std::string& planner,
            const OptionValues& options, ExperimentRun& run) {
  const PlannerEntry<Space>* entry = planners<Space>().find(planner);
  if (!entry) throw std::logic_error("the planner " + planner + " does not plan this problem (the experiment's reader checks it)");
  const Stopwatch setup;
  const auto built = entry->make(problem, options);
  run.setup_seconds = setup.seconds();
  const Stopwatch asking;
  auto report = built->plan(query);
  run.seconds = asking.seconds();
  record(std::move(report), run);
}


}  // namespace

struct ExperimentProblemFile::Loaded {
  std::variant<WorldProblem, ArmProblem> problem;

  bool is_car() const { return std::holds_alternative<WorldProblem>(problem) && !std::get<WorldProblem>(problem).cspace; }
};

ExperimentProblemFile::ExperimentProblemFile(const ExperimentProblem& problem) : loaded_(std::make_unique<Loaded>()) {
  std::vector<std::string> warnings;  // unknown fields of a problem file are not the experiment's concern
  if (problem.kind == ProblemKind::arm) {
    loaded_->problem = read_arm_problem(problem.file, &warnings);
    return;
  }
  WorldProblem world{std::make_unique<World>(read_world(problem.file, &warnings)), nullptr};
  if (!world.world->robot.car) world.cspace = std::make_unique<CSpace>(*world.world);
  loaded_->problem = std::move(world);
}

ExperimentProblemFile::~ExperimentProblemFile() = default;
ExperimentProblemFile::ExperimentProblemFile(ExperimentProblemFile&&) noexcept = default;
ExperimentProblemFile& ExperimentProblemFile::operator=(ExperimentProblemFile&&) noexcept = default;

std::vector<std::string> ExperimentProblemFile::query_names() const {
  std::vector<std::string> names;
  std::visit(
      [&](const auto& p) {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, ArmProblem>) {
          for (const auto& q : p.queries) names.push_back(q.name);
        } else {
          for (const auto& q : p.world->queries) names.push_back(q.name);
        }
      },
      loaded_->problem);
  return names;
}

// `read` applied to the registry entry named `name` in this problem's space (a world's translating
// planners first, then its rotating ones), or to null when there is none.
template <class Read>
auto ExperimentProblemFile::read_entry(const std::string& name, Read read) const {
  if (std::holds_alternative<ArmProblem>(loaded_->problem)) return read(planners<PlanarArm>().find(name));
  if (loaded_->is_car()) return read(planners<SteeredCar>().find(name));
  if (const auto* entry = planners<TranslatingRobot>().find(name)) return read(entry);
  return read(planners<RotatingRobot>().find(name));
}

const std::vector<OptionInfo>* ExperimentProblemFile::planner_options(const std::string& name) const {
  return read_entry(name, [](const auto* entry) -> const std::vector<OptionInfo>* { return entry ? &entry->options : nullptr; });
}

bool ExperimentProblemFile::planner_anytime(const std::string& name) const {
  return read_entry(name, [](const auto* entry) { return entry && entry->anytime; });
}

std::string ExperimentProblemFile::planner_names() const {
  if (std::holds_alternative<ArmProblem>(loaded_->problem)) return planners<PlanarArm>().names();
  if (loaded_->is_car()) return planners<SteeredCar>().names();
  return planners<TranslatingRobot>().names() + ", " + planners<RotatingRobot>().names();
}

void ExperimentProblemFile::require_planner_for_robot(const std::string& name) const {
  if (const auto* world = std::get_if<WorldProblem>(&loaded_->problem)) polyplan::require_planner_for_robot(*world->world, name);
}

void ExperimentProblemFile::build(const std::string& planner, const OptionValues& options) const {
  // Building is what checks the values; a planner built on a problem costs little beside a run.
  if (const auto* arm = std::get_if<ArmProblem>(&loaded_->problem)) {
    planners<PlanarArm>().find(planner)->make(*arm, options);
    return;
  }
  const WorldProblem& world = std::get<WorldProblem>(loaded_->problem);
  if (!world.cspace) planners<SteeredCar>().find(planner)->make(*world.world, options);
  else if (const auto* entry = planners<TranslatingRobot>().find(planner)) entry->make(*world.cspace, options);
  else planners<RotatingRobot>().find(planner)->make(*world.world, options);
}

void ExperimentProblemFile::run(const std::string& planner, const OptionValues& options, const std::string& query,
                                ExperimentRun& run) const {
  if (const auto* arm = std::get_if<ArmProblem>(&loaded_->problem))
    return run_in<PlanarArm>(*arm, query_named(arm->queries, query, arm->source), planner, options, run);
  const WorldProblem& world = std::get<WorldProblem>(loaded_->problem);
  const Query& asked = query_named(world.world->queries, query, world.world->source);
  if (!world.cspace) return run_in<SteeredCar>(*world.world, asked, planner, options, run);
  if (planners<TranslatingRobot>().find(planner)) return run_in<TranslatingRobot>(*world.cspace, asked, planner, options, run);
  run_in<RotatingRobot>(*world.world, asked, planner, options, run);
}

OptionValues options_for_run(const OptionValues& options, const std::vector<OptionInfo>& known, std::uint64_t seed,
                             double time_limit) {
  OptionValues values = options;
  const auto has = [&](const char* name) {
    return std::any_of(known.begin(), known.end(), [&](const OptionInfo& o) { return o.name == name; });
  };
  if (has("seed")) values.emplace_back("seed", std::to_string(seed));
  if (has("time")) values.emplace_back("time", detail::show_number(time_limit));
  return values;
}

}  // namespace polyplan
