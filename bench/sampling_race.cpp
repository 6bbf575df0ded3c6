// The race of the sampling planners (docs/sampling_race.md): polyplan's prm, lazyprm, rrt,
// rrtstar and rrtconnect against OMPL's PRM, LazyPRM, RRT, RRTstar and RRTConnect on the same
// problems, seed after seed, in three entries per planner:
//   polyplan          the registry's planner, shortcut=false (the raw search, as OMPL returns it);
//   OMPL (same check) OMPL's planner whose StateValidityChecker is the polyplan space's is_free and
//                     whose MotionValidator is its certified motion_is_free: literally the same code;
//   OMPL (discrete)   OMPL's planner with the same state check and its default DiscreteMotionValidator
//                     at its default resolution (1% of the space's extent), whose returned paths are
//                     then re-checked motion by motion with polyplan's certified test ("clipping").
// Same step (a fifth of the extent: OMPL's own default range, checked at start), goal bias 0.05,
// PRM and LazyPRM k = 10 nearest, RRT* k = ⌈e·(1 + 1/d)·log(n + 1)⌉ (OMPL's rewire factor set to 1).
//
// Measured: time to the first solution (polyplan: its first_solution_seconds, on the query's clock
// that starts as plan() is entered, and beside it the whole plan() call, which certifies the path
// once more; OMPL: solve() until an exact solution, or the first intermediate solution for RRTstar),
// success within 0.1 / 1 / 10 s, the median time (unsolved counted as +∞), RRT*'s best length at
// 0.1 / 1 / 10 s, and for OMPL's PRM when its roadmap first joined start and goal (WatchedPrm).
// Output: markdown tables on stdout, one SVG per problem in --out, every run in --csv.
//
// The default run (20 seeds, 10 s limits; RRT*, which always runs to its limit, 5 seeds of 10 s)
// takes about half an hour on one core, 17.5 minutes of it RRT*'s; --quick about a minute and a half.
//
// OMPL is a benchmark-only dependency (Debian: apt-get install libompl-dev); bench/CMakeLists.txt
// builds this program only when find_package(ompl) finds it.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/arm/arm_sampling_space.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/polygon_sampling_space.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include <polyplan/sampling/sampling_planner.hpp>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/ConnectionStrategy.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

namespace {

using namespace polyplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double goal_threshold = 1e-9;
constexpr std::size_t k_nearest = 10;  // PRM and LazyPRM: OMPL PRM's default, polyplan's default

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// ---------------------------------------------------------------------------------------------
// The contestants.

struct PlannerKind {
  std::string name;   // polyplan's registry name, and --planners'
  std::string label;  // in tables and pictures
  bool anytime;
};
const std::vector<PlannerKind> planner_kinds{{"prm", "PRM", false},
                                             {"lazyprm", "LazyPRM", false},
                                             {"rrt", "RRT", false},
                                             {"rrtstar", "RRT*", true},
                                             {"rrtconnect", "RRT-Connect", false}};

enum Entry { polyplan_entry = 0, ompl_same = 1, ompl_discrete = 2 };
constexpr std::array<const char*, 3> entry_labels{"polyplan", "OMPL (same check)", "OMPL (discrete check)"};

// How a returned path fares under polyplan's certified motion test.
enum class Clip { not_checked, certified, uncertified, collides };

struct Run {
  bool solved = false;
  double seconds = infinity;  // to the first solution (polyplan: its first_solution_seconds)
  double wall = infinity;     // polyplan: the whole plan() call, which certifies the path once more at its end
  double joined = infinity;   // OMPL's PRM: when its roadmap first joined start and goal (WatchedPrm)
  std::size_t joined_states = 0, joined_motions = 0;    // OMPL's PRM: the checks made by then
  double length = 0;                                    // of the first solution
  std::vector<std::pair<double, double>> improvements;  // (seconds, length): RRT*
  std::size_t states = 0;                               // polyplan: samples drawn; OMPL: state validity checks
  std::size_t motions = 0;  // motions checked (certified or, for the discrete check, checkMotion calls)
  Clip clip = Clip::not_checked;
};

// The best length found by `seconds` (infinity before the first solution).
double length_at(const Run& run, double seconds) {
  double best = infinity;
  for (const auto& [t, length] : run.improvements)
    if (t <= seconds) best = std::min(best, length);
  return best;
}

// ---------------------------------------------------------------------------------------------
// The polyplan space as OMPL's checkers. One space object is shared by every OMPL run of a
// problem; OMPL's PRM checks for solutions in a second thread that may add goal milestones,
// so its calls are serialised (only PRM's: an uncontended lock costs nanoseconds, a check microseconds).

template <class Space>
struct Bridge {
  using Configuration = typename Space::Configuration;
  SamplingSpace<Space>* space = nullptr;
  std::function<Configuration(const ob::State*)> configuration;  // an OMPL state as polyplan's configuration
  std::mutex* lock = nullptr;
  mutable std::size_t state_checks = 0, motion_checks = 0;

  bool is_free(const ob::State* s) const {
    ++state_checks;
    const Configuration c = configuration(s);
    if (lock) {
      std::lock_guard<std::mutex> guard(*lock);
      return space->is_free(c);
    }
    return space->is_free(c);
  }
  bool motion_is_free(const ob::State* a, const ob::State* b) const {
    ++motion_checks;
    const Configuration from = configuration(a), to = configuration(b);
    if (lock) {
      std::lock_guard<std::mutex> guard(*lock);
      return space->motion_is_free(from, to);
    }
    return space->motion_is_free(from, to);
  }
};

template <class Space>
class PolyplanValidity final : public ob::StateValidityChecker {
 public:
  PolyplanValidity(const ob::SpaceInformationPtr& si, const Bridge<Space>& bridge)
      : ob::StateValidityChecker(si), bridge_(&bridge) {}
  bool isValid(const ob::State* s) const override { return bridge_->is_free(s); }

 private:
  const Bridge<Space>* bridge_;
};

// checkMotion certifies the whole motion (both ends included) with the space's motion_is_free;
// the overload that reports the last valid state is conservative: on a refused motion it reports
// the motion's start (time 0), the only configuration known free without sampling.
template <class Space>
class PolyplanMotion final : public ob::MotionValidator {
 public:
  PolyplanMotion(const ob::SpaceInformationPtr& si, const Bridge<Space>& bridge)
      : ob::MotionValidator(si), bridge_(&bridge) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool free = bridge_->motion_is_free(s1, s2);
    (free ? valid_ : invalid_)++;
    return free;
  }
  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last_valid) const override {
    if (checkMotion(s1, s2)) return true;
    if (last_valid.first != nullptr) si_->copyState(last_valid.first, s1);
    last_valid.second = 0;
    return false;
  }

 private:
  const Bridge<Space>* bridge_;
};

// OMPL's LazyPRM joins a milestone to its 5 nearest within its range by default; polyplan's lazyprm
// to its k = 10 nearest at any distance. OMPL's own KStrategy(10) here, as PRM has by default.
class LazyPrmK final : public og::LazyPRM {
 public:
  LazyPrmK(const ob::SpaceInformationPtr& si, unsigned k) : og::LazyPRM(si), k_(k) {}
  void setup() override {
    og::LazyPRM::setup();
    connectionStrategy_ = og::KStrategy<Vertex>(k_, nn_);
  }

 private:
  unsigned k_;
};

// OMPL's PRM grows its roadmap in the calling thread and looks for a solution in a second one,
// every millisecond, under the lock that the growing thread holds while it checks a new
// milestone's motions; with slow (certified) checks the second thread can wait long for it, and
// the roadmap keeps growing meanwhile. solve() is timed as it is; this records besides when the
// roadmap first joined start and goal, seen by the connection filter, which addMilestone calls
// under that lock before each motion check (so at most one check, or one sample, late).
class WatchedPrm final : public og::PRM {
 public:
  // `counts()` gives the checks made so far (states, motions).
  WatchedPrm(const ob::SpaceInformationPtr& si, const Clock::time_point* t0, Run* run,
             std::function<std::pair<std::size_t, std::size_t>()> counts)
      : og::PRM(si), t0_(t0), run_(run), counts_(std::move(counts)) {
    setConnectionFilter([this](const Vertex&, const Vertex&) {
      if (!std::isfinite(run_->joined) && !startM_.empty() && !goalM_.empty() &&
          sameComponent(startM_.front(), goalM_.front())) {
        run_->joined = since(*t0_);
        std::tie(run_->joined_states, run_->joined_motions) = counts_();
      }
      return true;
    });
  }

 private:
  const Clock::time_point* t0_;
  Run* run_;
  std::function<std::pair<std::size_t, std::size_t>()> counts_;
};

// ---------------------------------------------------------------------------------------------
// A problem: a polygon world or an arm, its query, and how its configurations look to OMPL.

class RaceProblem {
 public:
  virtual ~RaceProblem() = default;
  virtual const std::string& name() const = 0;
  virtual std::string description() const = 0;
  virtual Run run(const PlannerKind& kind, Entry entry, std::uint64_t seed, double seconds) = 0;
};

// What differs between polygon worlds and arms.
template <class Space>
struct SpaceTraits;

template <>
struct SpaceTraits<TranslatingRobot> {
  static ob::StateSpacePtr ompl_space(const SamplingSpace<TranslatingRobot>&, const CSpace& cspace) {
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    const Bounds& box = *cspace.reference_box();  // both worlds have bounds (checked on loading)
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, to_double(box.xmin)), bounds.setHigh(0, to_double(box.xmax));
    bounds.setLow(1, to_double(box.ymin)), bounds.setHigh(1, to_double(box.ymax));
    space->setBounds(bounds);
    return space;
  }
  static ExactPoint configuration(const SamplingSpace<TranslatingRobot>& space, const ob::State* s) {
    const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
    return space.configuration(std::array<double, 2>{v[0], v[1]});
  }
  static void set_state(const SamplingSpace<TranslatingRobot>& space, const ExactPoint& p, ob::State* s) {
    std::array<double, 2> c{};
    space.coordinates(p, c);
    s->as<ob::RealVectorStateSpace::StateType>()->values[0] = c[0];
    s->as<ob::RealVectorStateSpace::StateType>()->values[1] = c[1];
  }
};

template <>
struct SpaceTraits<PlanarArm> {
  static ob::StateSpacePtr ompl_space(const SamplingSpace<PlanarArm>& space, const ArmProblem&) {
    auto compound = std::make_shared<ob::CompoundStateSpace>();
    for (std::size_t j = 0; j < space.dimension(); ++j)
      compound->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    compound->lock();
    return compound;
  }
  // SO2 keeps angles in [−π, π), polyplan in [0, 2π).
  static JointAngles configuration(const SamplingSpace<PlanarArm>& space, const ob::State* s) {
    const auto* compound = s->as<ob::CompoundState>();
    std::vector<double> c(space.dimension());
    for (std::size_t j = 0; j < c.size(); ++j)
      c[j] = normalize_angle(compound->as<ob::SO2StateSpace::StateType>(j)->value);
    return space.configuration(c);
  }
  static void set_state(const SamplingSpace<PlanarArm>& space, const JointAngles& q, ob::State* s) {
    std::vector<double> c(space.dimension());
    space.coordinates(q, c);
    auto* compound = s->as<ob::CompoundState>();
    for (std::size_t j = 0; j < c.size(); ++j)
      compound->as<ob::SO2StateSpace::StateType>(j)->value = c[j] >= std::numbers::pi ? c[j] - two_pi : c[j];
  }
};

template <class Space>
class RaceProblemOf final : public RaceProblem {
 public:
  using Configuration = typename Space::Configuration;
  using Problem = typename Space::Problem;
  using Query = typename Space::Query;

  // `problem` must outlive this. `clip` re-checks one motion of a returned path.
  RaceProblemOf(std::string name, std::string description, const Problem& problem, Query query,
                std::unique_ptr<SamplingSpace<Space>> space,
                std::function<Clip(const Configuration&, const Configuration&)> clip)
      : name_(std::move(name)), description_(std::move(description)), problem_(&problem), query_(std::move(query)),
        space_(std::move(space)), clip_(std::move(clip)) {
    ompl_space_ = SpaceTraits<Space>::ompl_space(*space_, problem);
    ompl_space_->setup();
    if (auto why = space_->query_not_free(query_)) throw std::runtime_error(name_ + ": " + *why);
  }

  const std::string& name() const override { return name_; }
  std::string description() const override { return description_; }
  double step() const { return space_->extent() / 5; }
  double ompl_default_range() const { return 0.2 * ompl_space_->getMaximumExtent(); }

  Run run(const PlannerKind& kind, Entry entry, std::uint64_t seed, double seconds) override {
    return entry == polyplan_entry ? run_polyplan(kind, seed, seconds) : run_ompl(kind, entry, seconds);
  }

 private:
  Run run_polyplan(const PlannerKind& kind, std::uint64_t seed, double seconds) {
    const OptionValues options{{"seed", std::to_string(seed)},
                               {"time", polyplan::detail::show_number(seconds)},
                               {"iterations", "100000000"},
                               {"shortcut", "false"}};
    const auto planner = planners<Space>().find(kind.name)->make(*problem_, options);
    const auto t0 = Clock::now();
    const PlanReport<Configuration> report = planner->plan(query_);
    const double wall = since(t0);
    Run run;
    run.states = static_cast<std::size_t>(report.facts.at(SamplingFacts::samples));
    run.motions = static_cast<std::size_t>(report.facts.at(SamplingFacts::motions_checked));
    if (!report.found) return run;
    run.solved = true;
    // The query's clock starts as plan() is entered: the start and goal checks are included.
    run.seconds = report.facts.at(SamplingFacts::first_solution_seconds);
    run.wall = wall;
    run.length = report.facts.at(SamplingFacts::raw_length);
    if (kind.anytime) {
      const auto& sampling = dynamic_cast<const SamplingPlanner<Space>&>(*planner);
      for (const SolutionImprovement& i : sampling.improvements()) run.improvements.emplace_back(i.seconds, i.length);
    }
    return run;
  }

  ob::PlannerPtr make_ompl(const PlannerKind& kind, const ob::SpaceInformationPtr& si, const Clock::time_point* t0,
                           Run* run, std::function<std::pair<std::size_t, std::size_t>()> counts) const {
    if (kind.name == "prm") {
      auto p = std::make_shared<WatchedPrm>(si, t0, run, std::move(counts));
      p->setMaxNearestNeighbors(k_nearest);
      return p;
    }
    if (kind.name == "lazyprm") return std::make_shared<LazyPrmK>(si, k_nearest);
    if (kind.name == "rrt") {
      auto p = std::make_shared<og::RRT>(si);
      p->setRange(step());
      p->setGoalBias(0.05);
      return p;
    }
    if (kind.name == "rrtstar") {
      auto p = std::make_shared<og::RRTstar>(si);
      p->setRange(step());
      p->setGoalBias(0.05);
      p->setKNearest(true);
      p->setRewireFactor(1.0);  // k = ⌈e·(1 + 1/d)·log(n + 1)⌉ as polyplan's (OMPL's default is 1.1 times that)
      return p;
    }
    auto p = std::make_shared<og::RRTConnect>(si);
    p->setRange(step());
    return p;
  }

  Run run_ompl(const PlannerKind& kind, Entry entry, double seconds) {
    std::mutex lock;
    Bridge<Space> bridge;
    bridge.space = space_.get();
    SamplingSpace<Space>* space = space_.get();
    bridge.configuration = [space](const ob::State* s) { return SpaceTraits<Space>::configuration(*space, s); };
    if (kind.name == "prm") bridge.lock = &lock;

    auto si = std::make_shared<ob::SpaceInformation>(ompl_space_);
    si->setStateValidityChecker(std::make_shared<PolyplanValidity<Space>>(si, bridge));
    if (entry == ompl_same) si->setMotionValidator(std::make_shared<PolyplanMotion<Space>>(si, bridge));
    si->setup();
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    ob::ScopedState<> start(ompl_space_), goal(ompl_space_);
    SpaceTraits<Space>::set_state(*space_, space_->start(query_), start.get());
    SpaceTraits<Space>::set_state(*space_, space_->goal(query_), goal.get());
    pdef->setStartAndGoalStates(start, goal, goal_threshold);
    Run run;
    Clock::time_point t0 = Clock::now();
    const auto counts = [&bridge, &si, entry] {
      const ob::MotionValidator& v = *si->getMotionValidator();
      return std::pair<std::size_t, std::size_t>(
          bridge.state_checks,
          entry == ompl_same ? bridge.motion_checks : v.getValidMotionCount() + v.getInvalidMotionCount());
    };
    const ob::PlannerPtr planner = make_ompl(kind, si, &t0, &run, counts);
    planner->setProblemDefinition(pdef);
    planner->setup();

    if (kind.anytime)
      pdef->setIntermediateSolutionCallback(
          [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost cost) {
            run.improvements.emplace_back(since(t0), cost.value());
          });
    t0 = Clock::now();
    const ob::PlannerStatus status = planner->solve(ob::timedPlannerTerminationCondition(seconds));
    const double wall = since(t0);
    std::tie(run.states, run.motions) = counts();
    if (status != ob::PlannerStatus::EXACT_SOLUTION || !pdef->hasExactSolution()) return run;
    run.solved = true;
    if (kind.anytime) {
      if (run.improvements.empty()) {
        run.solved = false;  // cannot happen: RRTstar reports each solution it finds
        return run;
      }
      run.seconds = run.improvements.front().first;
      run.length = run.improvements.front().second;
    } else {
      run.seconds = wall;
    }

    // The returned path, motion by motion, under polyplan's certified test.
    const auto* path = pdef->getSolutionPath()->as<og::PathGeometric>();
    if (!kind.anytime) run.length = path->length();
    run.clip = Clip::certified;
    for (std::size_t i = 0; i + 1 < path->getStateCount(); ++i) {
      const Clip c = clip_(SpaceTraits<Space>::configuration(*space_, path->getState(i)),
                           SpaceTraits<Space>::configuration(*space_, path->getState(i + 1)));
      if (c == Clip::collides) {
        run.clip = Clip::collides;
        break;
      }
      if (c == Clip::uncertified) run.clip = Clip::uncertified;
    }
    return run;
  }

  std::string name_, description_;
  const Problem* problem_;
  Query query_;
  std::unique_ptr<SamplingSpace<Space>> space_;
  std::function<Clip(const Configuration&, const Configuration&)> clip_;
  ob::StateSpacePtr ompl_space_;
};

// Everything a problem keeps alive.
struct ArmHolder {
  ArmProblem problem;
  std::unique_ptr<ArmCollisionChecker> checker;
};
struct WorldHolder {
  World world;
  std::unique_ptr<CSpace> cspace;
};

struct Loaded {
  std::vector<std::unique_ptr<ArmHolder>> arms;
  std::vector<std::unique_ptr<WorldHolder>> worlds;
  std::vector<std::unique_ptr<RaceProblem>> problems;
};

std::unique_ptr<RaceProblem> load_arm(Loaded& loaded, const std::string& data, const std::string& name,
                                      const std::string& query_name) {
  auto holder = std::make_unique<ArmHolder>();
  holder->problem = read_arm_problem(data + "/arms/" + name + ".json");
  holder->checker = std::make_unique<ArmCollisionChecker>(holder->problem);
  const ArmProblem& p = holder->problem;
  const auto q = std::find_if(p.queries.begin(), p.queries.end(),
                              [&](const ArmQuery& x) { return query_name.empty() || x.name == query_name; });
  if (q == p.queries.end()) throw std::runtime_error(name + ": no query " + query_name);
  const ArmCollisionChecker* checker = holder->checker.get();
  auto clip = [checker](const JointAngles& a, const JointAngles& b) {
    switch (certify_motion(*checker, a, b).verdict) {
      case MotionCertificate::Verdict::free: return Clip::certified;
      case MotionCertificate::Verdict::collides: return Clip::collides;
      default: return Clip::uncertified;
    }
  };
  std::ostringstream what;
  what << p.arm.joints() << "R arm, " << p.obstacles.size() << " obstacles, " << p.points.size() << " points, query "
       << q->name;
  auto problem = std::make_unique<RaceProblemOf<PlanarArm>>(name, what.str(), p, *q, arm_sampling_space(p), clip);
  loaded.arms.push_back(std::move(holder));
  return problem;
}

std::unique_ptr<RaceProblem> load_world(Loaded& loaded, const std::string& data, const std::string& name) {
  auto holder = std::make_unique<WorldHolder>();
  holder->world = read_world(data + "/worlds/" + name + ".json");
  if (!holder->world.bounds) throw std::runtime_error(name + ": the race needs a world with bounds (OMPL's box)");
  if (holder->world.queries.empty()) throw std::runtime_error(name + ": no query");
  holder->cspace = std::make_unique<CSpace>(holder->world);
  const CSpace* cspace = holder->cspace.get();
  auto clip = [cspace](const ExactPoint& a, const ExactPoint& b) {
    return check_segment(*cspace, a, b).valid ? Clip::certified : Clip::collides;
  };
  std::ostringstream what;
  what << "polygon world, " << holder->world.obstacles.size() << " obstacles, first query";
  auto problem = std::make_unique<RaceProblemOf<TranslatingRobot>>(
      name, what.str(), *holder->cspace, holder->world.queries.front(), polygon_sampling_space(*holder->cspace), clip);
  loaded.worlds.push_back(std::move(holder));
  return problem;
}

// ---------------------------------------------------------------------------------------------
// Statistics and text.

double median(std::vector<double> v) {
  if (v.empty()) return infinity;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;  // ∞ + x = ∞: a median among unsolved runs is ∞
}

std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "∞";
  char buffer[32];
  if (s < 0.001) std::snprintf(buffer, sizeof buffer, "%.0f µs", s * 1e6);
  else if (s < 1) std::snprintf(buffer, sizeof buffer, "%.1f ms", s * 1e3);
  else std::snprintf(buffer, sizeof buffer, "%.2f s", s);
  return buffer;
}

std::string number_text(double x, int digits = 3) {
  if (!std::isfinite(x)) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

std::string count_text(double x) {
  char buffer[32];
  if (x >= 1e6) std::snprintf(buffer, sizeof buffer, "%.2fM", x / 1e6);
  else if (x >= 1e4) std::snprintf(buffer, sizeof buffer, "%.1fk", x / 1e3);
  else std::snprintf(buffer, sizeof buffer, "%.0f", x);
  return buffer;
}

struct Results {
  // [problem][planner][entry] -> runs
  std::vector<std::vector<std::array<std::vector<Run>, 3>>> runs;
};

std::size_t solved_within(const std::vector<Run>& runs, double seconds) {
  return static_cast<std::size_t>(
      std::count_if(runs.begin(), runs.end(), [&](const Run& r) { return r.solved && r.seconds <= seconds; }));
}

double median_seconds(const std::vector<Run>& runs) {
  std::vector<double> t;
  for (const Run& r : runs) t.push_back(r.solved ? r.seconds : infinity);
  return median(t);
}

// OMPL's PRM: the median time its roadmap first joined start and goal (WatchedPrm).
double median_joined(const std::vector<Run>& runs) {
  std::vector<double> t;
  for (const Run& r : runs) t.push_back(r.joined);
  return median(t);
}

template <class F>
double median_of(const std::vector<Run>& runs, F f) {
  std::vector<double> v;
  for (const Run& r : runs) v.push_back(static_cast<double>(f(r)));
  return median(v);
}

// The median best length at `seconds` over the runs solved by then, and how many.
std::pair<double, std::size_t> cost_at(const std::vector<Run>& runs, double seconds) {
  std::vector<double> v;
  for (const Run& r : runs)
    if (double l = length_at(r, seconds); std::isfinite(l)) v.push_back(l);
  return {median(v), v.size()};
}

std::string ratio_text(double ours, double theirs) {
  if (!std::isfinite(ours) && !std::isfinite(theirs)) return "n/a";
  if (!std::isfinite(theirs)) return "0 (OMPL ∞)";
  if (!std::isfinite(ours)) return "∞";
  return number_text(ours / theirs, 2);
}

// ---------------------------------------------------------------------------------------------
// Pictures: per problem one SVG, a panel per planner (success rate against time, log axis) and a
// panel of RRT*'s length against time.

struct Curve {
  std::string label, colour, dash;
  std::vector<std::pair<double, double>> points;  // (seconds, value)
};

class Panel {
 public:
  Panel(double x, double y, double w, double h, std::string title, double t_max, double y_min, double y_max,
        std::string y_label)
      : x_(x), y_(y), w_(w), h_(h), title_(std::move(title)), t_max_(t_max), y_min_(y_min), y_max_(y_max),
        y_label_(std::move(y_label)) {
    if (!(y_max_ > y_min_)) y_max_ = y_min_ + 1;
  }

  double sx(double t) const {
    const double lo = std::log10(t_min_), hi = std::log10(t_max_);
    return x_ + w_ * (std::log10(std::clamp(t, t_min_, t_max_)) - lo) / (hi - lo);
  }
  double sy(double v) const { return y_ + h_ - h_ * (v - y_min_) / (y_max_ - y_min_); }

  void draw(std::ostream& out, const std::vector<Curve>& curves, bool percent) const {
    out << "<rect x='" << x_ << "' y='" << y_ << "' width='" << w_ << "' height='" << h_
        << "' fill='#fff' stroke='#222' stroke-width='1'/>\n";
    out << "<text x='" << x_ + w_ / 2 << "' y='" << y_ - 8
        << "' text-anchor='middle' font-size='14' font-weight='bold'>" << title_ << "</text>\n";
    for (double t = t_min_; t <= t_max_ * 1.0001; t *= 10) {
      const double px = sx(t);
      out << "<line x1='" << px << "' y1='" << y_ << "' x2='" << px << "' y2='" << y_ + h_ << "' stroke='#ddd'/>\n";
      out << "<text x='" << px << "' y='" << y_ + h_ + 15 << "' text-anchor='middle' font-size='11'>" << tick(t)
          << "</text>\n";
    }
    for (int i = 0; i <= 4; ++i) {
      const double v = y_min_ + (y_max_ - y_min_) * i / 4, py = sy(v);
      out << "<line x1='" << x_ << "' y1='" << py << "' x2='" << x_ + w_ << "' y2='" << py << "' stroke='#eee'/>\n";
      out << "<text x='" << x_ - 5 << "' y='" << py + 4 << "' text-anchor='end' font-size='11'>"
          << (percent ? std::to_string(static_cast<int>(std::lround(v * 100))) + "%" : number_text(v, 2))
          << "</text>\n";
    }
    out << "<text x='" << x_ + w_ / 2 << "' y='" << y_ + h_ + 30
        << "' text-anchor='middle' font-size='11'>time (s, log)</text>\n";
    out << "<text x='" << x_ - 42 << "' y='" << y_ + h_ / 2
        << "' text-anchor='middle' font-size='11' transform='rotate(-90 " << x_ - 42 << ' ' << y_ + h_ / 2 << ")'>"
        << y_label_ << "</text>\n";
    for (const Curve& c : curves) {
      if (c.points.empty()) continue;
      out << "<polyline fill='none' stroke='" << c.colour << "' stroke-width='2'"
          << (c.dash.empty() ? "" : " stroke-dasharray='" + c.dash + "'") << " points='";
      for (const auto& [t, v] : c.points) out << sx(t) << ',' << sy(v) << ' ';
      out << "'/>\n";
    }
  }

 private:
  static std::string tick(double t) {
    if (t < 0.01) return std::to_string(static_cast<int>(std::lround(t * 1000))) + " ms";
    if (t < 1) return number_text(t, t < 0.1 ? 2 : 1) + " s";
    return std::to_string(static_cast<int>(std::lround(t))) + " s";
  }
  double x_, y_, w_, h_;
  std::string title_;
  double t_min_ = 1e-3, t_max_;
  double y_min_, y_max_;
  std::string y_label_;
};

constexpr std::array<const char*, 3> entry_colours{"#1f77b4", "#e6550d", "#31a354"};
constexpr std::array<const char*, 3> entry_dashes{"", "", "6 4"};

// The fraction of runs solved by each time: a step curve from 1 ms to t_max.
std::vector<std::pair<double, double>> success_curve(const std::vector<Run>& runs, double t_max) {
  std::vector<double> times;
  for (const Run& r : runs)
    if (r.solved) times.push_back(std::max(r.seconds, 1e-3));
  std::sort(times.begin(), times.end());
  const double n = static_cast<double>(runs.size());
  std::vector<std::pair<double, double>> points{{1e-3, 0}};
  double solved = 0;
  for (double t : times) {
    if (t > t_max) break;
    points.emplace_back(t, solved / n);
    solved += 1;
    points.emplace_back(t, solved / n);
  }
  points.emplace_back(t_max, solved / n);
  return points;
}

// RRT*'s median best length over all runs (unsolved: +∞, so the curve starts once half have a
// solution), at the times where some run improved.
std::vector<std::pair<double, double>> cost_curve(const std::vector<Run>& runs, double t_max) {
  std::vector<double> times;
  for (const Run& r : runs)
    for (const auto& [t, l] : r.improvements) times.push_back(std::max(t, 1e-3));
  times.push_back(t_max);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<std::pair<double, double>> points;
  for (double t : times) {
    if (t > t_max) break;
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(length_at(r, t));
    const double m = median(v);
    if (std::isfinite(m)) {
      if (!points.empty()) points.emplace_back(t, points.back().second);  // a step
      points.emplace_back(t, m);
    }
  }
  return points;
}

void write_svg(const std::string& path, const RaceProblem& problem,
               const std::vector<std::array<std::vector<Run>, 3>>& runs, const std::vector<std::size_t>& planners_run,
               double seconds, double rrtstar_seconds) {
  const double pw = 300, ph = 190, gap_x = 80, gap_y = 85, left = 70, top = 95;
  const std::size_t columns = 3;
  const std::size_t panels = planners_run.size() + 1;
  const std::size_t rows = (panels + columns - 1) / columns;
  const double width = left + columns * (pw + gap_x), height = top + rows * (ph + gap_y);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height << "' viewBox='0 0 "
      << width << ' ' << height << "' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='#fafafa'/>\n";
  out << "<text x='" << left << "' y='28' font-size='18' font-weight='bold'>" << problem.name() << ": "
      << problem.description() << "</text>\n";
  // Legend.
  double lx = left;
  for (std::size_t e = 0; e < 3; ++e) {
    out << "<line x1='" << lx << "' y1='46' x2='" << lx + 30 << "' y2='46' stroke='" << entry_colours[e]
        << "' stroke-width='2'" << (*entry_dashes[e] ? std::string(" stroke-dasharray='") + entry_dashes[e] + "'" : "")
        << "/>";
    out << "<text x='" << lx + 36 << "' y='50' font-size='13'>" << entry_labels[e] << "</text>\n";
    lx += 230;
  }
  double cost_min = infinity, cost_max = 0;
  std::size_t panel = 0;
  for (std::size_t i = 0; i < planners_run.size(); ++i, ++panel) {
    const PlannerKind& kind = planner_kinds[planners_run[i]];
    const double t_max = kind.anytime ? rrtstar_seconds : seconds;
    Panel p(left + (panel % columns) * (pw + gap_x), top + (panel / columns) * (ph + gap_y), pw, ph,
            kind.label + ": solved by time t", t_max, 0, 1, "runs solved");
    std::vector<Curve> curves;
    for (std::size_t e = 0; e < 3; ++e)
      curves.push_back({entry_labels[e], entry_colours[e], entry_dashes[e], success_curve(runs[i][e], t_max)});
    p.draw(out, curves, true);
    if (kind.anytime)
      for (std::size_t e = 0; e < 3; ++e)
        for (const Run& r : runs[i][e])
          for (const auto& [t, l] : r.improvements) cost_min = std::min(cost_min, l), cost_max = std::max(cost_max, l);
  }
  const auto star =
      std::find_if(planners_run.begin(), planners_run.end(), [](std::size_t k) { return planner_kinds[k].anytime; });
  if (star != planners_run.end()) {
    const std::size_t i = static_cast<std::size_t>(star - planners_run.begin());
    std::vector<Curve> curves;
    double shown_max = 0;
    for (std::size_t e = 0; e < 3; ++e) {
      curves.push_back({entry_labels[e], entry_colours[e], entry_dashes[e], cost_curve(runs[i][e], rrtstar_seconds)});
      for (const auto& [t, v] : curves.back().points) shown_max = std::max(shown_max, v);
    }
    if (shown_max > 0) cost_max = shown_max;
    if (!std::isfinite(cost_min)) cost_min = 0, cost_max = 1;
    const double pad = (cost_max - cost_min) * 0.05 + 1e-9;
    Panel p(left + (panel % columns) * (pw + gap_x), top + (panel / columns) * (ph + gap_y), pw, ph,
            "RRT*: median path length", rrtstar_seconds, cost_min - pad, cost_max + pad,
            "length (median of all seeds)");
    p.draw(out, curves, false);
  }
  out << "</svg>\n";
}

// ---------------------------------------------------------------------------------------------

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The sampling planners' race: polyplan against OMPL on the same problems with the same checker"};
  std::size_t seeds = 20, rrtstar_seeds = 5;
  double seconds = 10, rrtstar_seconds = 10;
  std::string problems_text, planners_text, out_dir, csv_path, data = POLYPLAN_DATA_DIR;
  bool quick = false;
  std::uint64_t ompl_seed = 1;
  app.add_option("--seeds", seeds, "seeds per problem, planner and entry (polyplan seeds 1..N)");
  app.add_option("--seconds", seconds, "time limit of every run but RRT*'s, seconds");
  app.add_option("--rrtstar-seconds", rrtstar_seconds, "RRT*'s run time (it always runs to its limit), seconds");
  app.add_option(
      "--rrtstar-seeds", rrtstar_seeds,
      "seeds for RRT*, whose every run lasts --rrtstar-seconds (each seed adds 7 problems x 3 entries x that)");
  app.add_option("--problems", problems_text,
                 "comma-separated: two_link_points, three_link_forest, four_link_forest, "
                 "four_link_dense, six_link_forest, maze, office (default: all)");
  app.add_option("--planners", planners_text, "comma-separated: prm, lazyprm, rrt, rrtstar, rrtconnect (default: all)");
  app.add_option("--out", out_dir, "directory for the SVG curves (none: no pictures)");
  app.add_option("--csv", csv_path, "also write every run as a CSV line to this file");
  app.add_option("--data", data, "polyplan's data directory");
  app.add_option("--ompl-seed", ompl_seed, "ompl::RNG::setSeed, once for the whole process");
  app.add_flag("--quick", quick, "smoke run: 3 seeds, 1 s limits");
  CLI11_PARSE(app, argc, argv);
  if (quick)
    seeds = rrtstar_seeds = 3, seconds = std::min(seconds, 1.0), rrtstar_seconds = std::min(rrtstar_seconds, 1.0);
  if (seeds == 0 || rrtstar_seeds == 0 || !(seconds > 0) || !(rrtstar_seconds > 0)) {
    std::cerr << "sampling_race: seeds, seconds and rrtstar-seconds must be positive\n";
    return 2;
  }

  // Before any OMPL object: every RNG OMPL makes takes its seed from this one, in the order made.
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(ompl_seed));
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  const std::vector<std::pair<std::string, std::string>> all_problems{{"two_link_points", "hard"},
                                                                      {"three_link_forest", ""},
                                                                      {"four_link_forest", ""},
                                                                      {"four_link_dense", ""},
                                                                      {"six_link_forest", ""},
                                                                      {"maze", ""},
                                                                      {"office", ""}};
  std::vector<std::string> chosen = problems_text.empty() ? std::vector<std::string>{} : split(problems_text);
  std::vector<std::size_t> planners_run;
  for (const std::string& name : planners_text.empty() ? std::vector<std::string>{} : split(planners_text)) {
    const auto k =
        std::find_if(planner_kinds.begin(), planner_kinds.end(), [&](const PlannerKind& p) { return p.name == name; });
    if (k == planner_kinds.end()) {
      std::cerr << "sampling_race: unknown planner " << name << '\n';
      return 2;
    }
    planners_run.push_back(static_cast<std::size_t>(k - planner_kinds.begin()));
  }
  if (planners_run.empty())
    for (std::size_t k = 0; k < planner_kinds.size(); ++k) planners_run.push_back(k);

  Loaded loaded;
  try {
    for (const auto& [name, query] : all_problems) {
      if (!chosen.empty() && std::find(chosen.begin(), chosen.end(), name) == chosen.end()) continue;
      if (name == "maze" || name == "office") loaded.problems.push_back(load_world(loaded, data, name));
      else loaded.problems.push_back(load_arm(loaded, data, name, query));
    }
  } catch (const std::exception& e) {
    std::cerr << "sampling_race: " << e.what() << '\n';
    return 2;
  }
  for (const std::string& name : chosen)
    if (std::none_of(all_problems.begin(), all_problems.end(), [&](const auto& p) { return p.first == name; })) {
      std::cerr << "sampling_race: unknown problem " << name << '\n';
      return 2;
    }

  // The step both libraries take: polyplan's default (a fifth of its extent) against OMPL's
  // default range (0.2 · the state space's maximum extent); OMPL is given polyplan's explicitly.
  for (const auto& p : loaded.problems) {
    double step = 0, ompl_range = 0;
    if (auto* arm = dynamic_cast<RaceProblemOf<PlanarArm>*>(p.get()))
      step = arm->step(), ompl_range = arm->ompl_default_range();
    if (auto* world = dynamic_cast<RaceProblemOf<TranslatingRobot>*>(p.get()))
      step = world->step(), ompl_range = world->ompl_default_range();
    std::cerr << p->name() << ": " << p->description() << "; step " << step << " (OMPL's default range " << ompl_range
              << (std::abs(step - ompl_range) <= 1e-12 * step ? ", the same" : ", DIFFERENT") << ")\n";
  }
  const bool star =
      std::any_of(planners_run.begin(), planners_run.end(), [](std::size_t k) { return planner_kinds[k].anytime; });
  std::cerr << "sampling_race: " << seeds << " seeds, limit " << seconds << " s; RRT* " << rrtstar_seeds << " seeds of "
            << rrtstar_seconds << " s each, which alone take "
            << (star ? static_cast<double>(loaded.problems.size() * rrtstar_seeds * 3) * rrtstar_seconds / 60 : 0)
            << " min\n";

  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    if (!csv) {
      std::cerr << "sampling_race: cannot write " << csv_path << '\n';
      return 2;
    }
    csv << "problem,planner,entry,seed,solved,seconds,plan_seconds,length,states,motions,clip,joined_seconds,joined_"
           "states,"
           "joined_motions\n";
  }
  const auto began = Clock::now();
  Results results;
  results.runs.resize(loaded.problems.size());
  for (std::size_t pi = 0; pi < loaded.problems.size(); ++pi) {
    RaceProblem& problem = *loaded.problems[pi];
    results.runs[pi].resize(planners_run.size());
    for (std::size_t i = 0; i < planners_run.size(); ++i) {
      const PlannerKind& kind = planner_kinds[planners_run[i]];
      const double limit = kind.anytime ? rrtstar_seconds : seconds;
      const auto t0 = Clock::now();
      std::ostringstream line;
      line << '[' << problem.name() << ' ' << kind.name << ']';
      for (std::size_t e = 0; e < 3; ++e) {
        auto& runs = results.runs[pi][i][e];
        const std::size_t n = kind.anytime ? rrtstar_seeds : seeds;
        for (std::uint64_t seed = 1; seed <= n; ++seed) {
          runs.push_back(problem.run(kind, static_cast<Entry>(e), seed, limit));
          if (csv.is_open()) {
            const Run& r = runs.back();
            constexpr std::array<const char*, 4> clips{"", "certified", "uncertified", "collides"};
            csv << problem.name() << ',' << kind.name << ',' << entry_labels[e] << ',' << seed << ',' << r.solved << ','
                << r.seconds << ',' << r.wall << ',' << r.length << ',' << r.states << ',' << r.motions << ','
                << clips[static_cast<std::size_t>(r.clip)] << ',' << r.joined << ',' << r.joined_states << ','
                << r.joined_motions << '\n';
          }
        }
        line << ' ' << entry_labels[e] << ' ' << solved_within(runs, limit) << '/' << n << " in "
             << seconds_text(median_seconds(runs)) << (e < 2 ? ";" : "");
      }
      std::cerr << line.str() << " (" << std::lround(since(t0)) << " s; " << std::lround(since(began))
                << " s so far)\n";
    }
    if (!out_dir.empty()) {
      std::filesystem::create_directories(out_dir);
      write_svg(out_dir + "/" + problem.name() + ".svg", problem, results.runs[pi], planners_run, seconds,
                rrtstar_seconds);
    }
  }

  // The tables.
  std::cout
      << "# Sampling race: polyplan against OMPL " << OMPL_MAJOR_VERSION << '.' << OMPL_MINOR_VERSION << '.'
      << OMPL_PATCH_VERSION << "\n\n"
      << seeds << " seeds per entry; time limit " << seconds << " s (RRT*: " << rrtstar_seeds << " seeds, each run "
      << rrtstar_seconds << " s); polyplan with shortcut=false; OMPL seeded once per process (ompl::RNG::setSeed("
      << ompl_seed << ")).\n"
      << "Time = to the first solution (median over all seeds, unsolved = ∞; polyplan: first_solution_seconds). "
         "ratio = polyplan / OMPL (same check): the goal is ≤ 0.5. Other times: polyplan's whole plan() call (the "
         "returned path certified once more) and its ratio; for OMPL's PRM, when its roadmap first joined start "
         "and goal (its solve() notices that later, in a second thread) and polyplan's ratio to that.\n"
      << "states: polyplan samples drawn, OMPL state validity checks; motions: motions checked. clip: OMPL's returned "
         "paths with a motion polyplan does not certify (collides: a configuration on it collides).\n\n";
  const std::vector<double> marks{0.1, 1, 10};
  for (std::size_t pi = 0; pi < loaded.problems.size(); ++pi) {
    const RaceProblem& problem = *loaded.problems[pi];
    std::cout << "## " << problem.name() << " (" << problem.description() << ")\n\n"
              << "| planner | entry | ≤ 0.1 s | ≤ 1 s | ≤ 10 s | median time | ratio | other times | states | motions "
                 "| clip |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < planners_run.size(); ++i) {
      const PlannerKind& kind = planner_kinds[planners_run[i]];
      const double limit = kind.anytime ? rrtstar_seconds : seconds;
      const auto& entries = results.runs[pi][i];
      for (std::size_t e = 0; e < 3; ++e) {
        const auto& runs = entries[e];
        std::cout << "| " << kind.label << " | " << entry_labels[e];
        for (double m : marks) {
          if (m > limit * 1.0001) std::cout << " | —";
          else std::cout << " | " << solved_within(runs, m) << '/' << runs.size();
        }
        std::cout << " | " << seconds_text(median_seconds(runs)) << " | ";
        if (e == polyplan_entry) std::cout << ratio_text(median_seconds(runs), median_seconds(entries[ompl_same]));
        std::cout << " | ";
        if (e == polyplan_entry && !kind.anytime) {
          std::vector<double> w;
          for (const Run& r : runs) w.push_back(r.wall);
          std::cout << "plan() " << seconds_text(median(w)) << " (ratio "
                    << ratio_text(median(w), median_seconds(entries[ompl_same])) << ')';
          if (kind.name == "prm")
            std::cout << "; ratio to OMPL's roadmap joined "
                      << ratio_text(median_seconds(runs), median_joined(entries[ompl_same]));
        }
        if (e != polyplan_entry && kind.name == "prm")
          std::cout << "roadmap joined " << seconds_text(median_joined(runs));
        std::cout << " | " << count_text(median_of(runs, [](const Run& r) { return r.states; })) << " | "
                  << count_text(median_of(runs, [](const Run& r) { return r.motions; })) << " | ";
        if (e != polyplan_entry) {
          std::size_t solved = 0, clipped = 0, collides = 0;
          for (const Run& r : runs) {
            if (r.clip == Clip::not_checked) continue;
            ++solved;
            if (r.clip != Clip::certified) ++clipped;
            if (r.clip == Clip::collides) ++collides;
          }
          std::cout << clipped << " of " << solved;
          if (clipped > 0) std::cout << " (collides: " << collides << ")";
        }
        std::cout << " |\n";
      }
    }
    std::cout << '\n';
    const auto star_it =
        std::find_if(planners_run.begin(), planners_run.end(), [](std::size_t k) { return planner_kinds[k].anytime; });
    if (star_it != planners_run.end()) {
      const auto& entries = results.runs[pi][static_cast<std::size_t>(star_it - planners_run.begin())];
      std::cout << "RRT* length (median over the seeds solved by then, and how many):\n\n"
                << "| entry | at 0.1 s | at 1 s | at 10 s |\n|---|---|---|---|\n";
      for (std::size_t e = 0; e < 3; ++e) {
        std::cout << "| " << entry_labels[e];
        for (double m : marks) {
          if (m > rrtstar_seconds * 1.0001) {
            std::cout << " | —";
            continue;
          }
          const auto [c, n] = cost_at(entries[e], m);
          std::cout << " | " << number_text(c) << " (" << n << '/' << entries[e].size() << ')';
        }
        std::cout << " |\n";
      }
      std::cout << '\n';
    }
  }

  // The goals, in one table.
  std::cout
      << "## Goals: polyplan's median time ≤ ½ OMPL's (same check); RRT* length at 1 s ≤ OMPL's\n\n"
         "Each cell: the ratio of the median times, whether ≤ 0.5, and in parentheses the ratio with polyplan's whole "
         "plan() call (and for PRM, to the time OMPL's roadmap joined start and goal). RRT*: the median length at 1 s "
         "(runs with a path by then).\n\n| problem |";
  for (std::size_t k : planners_run) std::cout << ' ' << planner_kinds[k].label << " |";
  if (star) std::cout << " RRT* length at 1 s (polyplan / OMPL) |";
  std::cout << "\n|---|";
  for (std::size_t k = 0; k < planners_run.size() + (star ? 1 : 0); ++k) std::cout << "---|";
  std::cout << '\n';
  for (std::size_t pi = 0; pi < loaded.problems.size(); ++pi) {
    std::cout << "| " << loaded.problems[pi]->name() << " |";
    for (std::size_t i = 0; i < planners_run.size(); ++i) {
      const auto& entries = results.runs[pi][i];
      const double ours = median_seconds(entries[polyplan_entry]), theirs = median_seconds(entries[ompl_same]);
      const bool met = std::isfinite(ours) && (!std::isfinite(theirs) || ours <= theirs / 2);
      std::cout << ' ' << ratio_text(ours, theirs) << (met ? " yes" : " **no**");
      if (!planner_kinds[planners_run[i]].anytime) {
        std::vector<double> w;
        for (const Run& r : entries[polyplan_entry]) w.push_back(r.wall);
        std::cout << " (plan() " << ratio_text(median(w), theirs);
        if (planner_kinds[planners_run[i]].name == "prm")
          std::cout << "; joined " << ratio_text(ours, median_joined(entries[ompl_same]));
        std::cout << ')';
      }
      std::cout << " |";
    }
    if (star) {
      const auto star_it = std::find_if(planners_run.begin(), planners_run.end(),
                                        [](std::size_t k) { return planner_kinds[k].anytime; });
      const auto& entries = results.runs[pi][static_cast<std::size_t>(star_it - planners_run.begin())];
      const auto [ours, n_ours] = cost_at(entries[polyplan_entry], 1);
      const auto [theirs, n_theirs] = cost_at(entries[ompl_same], 1);
      // Met when polyplan has a path in at least as many runs by 1 s, and its median is no longer.
      const bool met = std::isfinite(ours) && n_ours >= n_theirs && (!std::isfinite(theirs) || ours <= theirs);
      std::cout << ' ' << number_text(ours) << " (" << n_ours << ") / " << number_text(theirs) << " (" << n_theirs
                << ")"
                << (met                 ? " yes"
                    : n_ours < n_theirs ? " **no** (fewer runs solved)"
                                        : " **no**")
                << " |";
    }
    std::cout << '\n';
  }

  // Against what OMPL's users run: its default discrete check, which is faster and unsafe.
  std::cout
      << "\n## Against OMPL with its default discrete check\n\n"
         "Each cell: polyplan's median time / OMPL's (discrete check), and how many of OMPL's returned paths collide "
         "(a configuration on a motion of it collides: found by polyplan's certified test) of those it returned.\n\n| "
         "problem |";
  for (std::size_t k : planners_run) std::cout << ' ' << planner_kinds[k].label << " |";
  std::cout << "\n|---|";
  for (std::size_t k = 0; k < planners_run.size(); ++k) std::cout << "---|";
  std::cout << '\n';
  for (std::size_t pi = 0; pi < loaded.problems.size(); ++pi) {
    std::cout << "| " << loaded.problems[pi]->name() << " |";
    for (std::size_t i = 0; i < planners_run.size(); ++i) {
      const auto& entries = results.runs[pi][i];
      std::size_t returned = 0, collide = 0;
      for (const Run& r : entries[ompl_discrete]) {
        if (r.clip == Clip::not_checked) continue;
        ++returned;
        collide += r.clip == Clip::collides;
      }
      std::cout << ' ' << ratio_text(median_seconds(entries[polyplan_entry]), median_seconds(entries[ompl_discrete]))
                << "; " << collide << " of " << returned << " collide |";
    }
    std::cout << '\n';
  }
  std::cout << "\nTotal wall time " << std::lround(since(began)) << " s.\n";
  return 0;
}
