// The car's race (docs/car_race.md): polyplan's hybrid-astar, rrtstar and rrtconnect on the
// shipped car worlds against OMPL's RRTstar and RRTConnect on its DubinsStateSpace (a car that
// cannot reverse) or ReedsSheppStateSpace, seed after seed, with two checkers for OMPL:
//   same check  OMPL's StateValidityChecker is polyplan's car space's is_free and its MotionValidator
//               the space's certified motion_is_free (car/car_sampling_space.hpp): the same code
//               polyplan's planners call;
//   discrete    OMPL's default DiscreteMotionValidator (poses every 1% of the space's extent,
//               each checked by the same is_free); its returned paths are then re-checked motion
//               by motion with the certified test, and densely (every R/200 of arc length) for
//               poses that hit an obstacle: "colliding" counts the paths with such a pose.
// Same step (a fifth of the car space's extent: OMPL's range set to it), goal bias 0.05, RRT* with
// its k-nearest rewiring, polyplan with shortcut=false (the raw search, as OMPL returns it).
//
// Measured per world: time to the first solution (polyplan: first_solution_seconds; OMPL: solve()
// until an exact solution, or RRTstar's first intermediate solution) over --seeds seeds, median
// and success count within --seconds; the length at 1 s (--length-seconds) of RRT* and of
// hybrid-astar's answer; and for OMPL's discrete checker how many returned paths collide.
// Output: a markdown table per world on stdout. Each OMPL run is a child process (in_child), so an
// assertion of OMPL's own that aborts it is counted, not the end of the race.
//
// OMPL is a benchmark-only dependency (Debian: apt-get install libompl-dev).
#include <polyplan/car/car_motion.hpp>
#include <polyplan/car/car_query.hpp>
#include <polyplan/car/car_sampling_space.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include <polyplan/sampling/sampling_planner.hpp>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <CLI/CLI.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
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

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Run {
  bool aborted = false;  // the run's process stopped (OMPL on one of its own assertions: see in_child)
  bool solved = false;
  double seconds = infinity;  // to the first solution
  double length = infinity;   // of the first solution, or at --length-seconds for RRT*
  bool collides = false;      // OMPL's discrete checker: a pose of its path hits an obstacle
  bool certified = true;      // every motion passes polyplan's certified test
};

// ---------------------------------------------------------------------------------------------
// OMPL on the car: its SE2-based Dubins or Reeds–Shepp space over the world's box.

CarState state_of(const ob::State* s) {
  const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
  return {{se2->getX(), se2->getY(), se2->getYaw()}, {}};
}

class SameValidity final : public ob::StateValidityChecker {
 public:
  SameValidity(const ob::SpaceInformationPtr& si, SamplingSpace<SteeredCar>& space)
      : ob::StateValidityChecker(si), space_(&space) {}
  bool isValid(const ob::State* s) const override { return space_->is_free(state_of(s)); }

 private:
  SamplingSpace<SteeredCar>* space_;
};

// The whole motion certified; on a refusal the last valid state is the motion's start (time 0),
// the only one known free without sampling.
class SameMotion final : public ob::MotionValidator {
 public:
  SameMotion(const ob::SpaceInformationPtr& si, SamplingSpace<SteeredCar>& space)
      : ob::MotionValidator(si), space_(&space) {}
  bool checkMotion(const ob::State* a, const ob::State* b) const override {
    const bool free = space_->motion_is_free(state_of(a), state_of(b));
    (free ? valid_ : invalid_)++;
    return free;
  }
  bool checkMotion(const ob::State* a, const ob::State* b, std::pair<ob::State*, double>& last_valid) const override {
    if (checkMotion(a, b)) return true;
    if (last_valid.first != nullptr) si_->copyState(last_valid.first, a);
    last_valid.second = 0;
    return false;
  }

 private:
  SamplingSpace<SteeredCar>* space_;
};

struct CarProblem {
  std::string name;
  World world;
  std::unique_ptr<SamplingSpace<SteeredCar>> space;  // polyplan's, for OMPL's checkers and the re-check
  CarCollision collision;
  double step = 0;
  CarPose start, goal;

  explicit CarProblem(const std::string& file, std::string name_)
      : name(std::move(name_)), world(read_world(file)), space(car_sampling_space(world)), collision(world) {
    step = space->extent() / 5;
    start = start_pose(world.queries.at(0));
    goal = goal_pose(world.queries.at(0));
  }
  const CarSteering& steering() const { return *world.robot.car; }
};

// A pose every R/200 along the curve a → b that the body hits: the re-check of a discrete
// checker's path.
bool dense_hit(const CarProblem& p, const CarPose& a, const CarPose& b) {
  const SteeringPath path = shortest_car_path(p.steering(), a, b);
  const double spacing = p.steering().turning_radius / 200;
  for (double s = 0; s <= path.length(); s += spacing)
    if (!p.collision.pose_is_free(pose_along(path, a, p.steering().turning_radius, s))) return true;
  return !p.collision.pose_is_free(b);
}

enum class Checker { same, discrete };

Run run_ompl(CarProblem& p, bool rrtstar, Checker checker, double seconds) {
  const double radius = p.steering().turning_radius;
  ob::StateSpacePtr space = p.steering().reverse ? ob::StateSpacePtr(std::make_shared<ob::ReedsSheppStateSpace>(radius))
                                                 : ob::StateSpacePtr(std::make_shared<ob::DubinsStateSpace>(radius));
  const CarSamplingBox box = car_sampling_box(p.world);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, box.xmin), bounds.setHigh(0, box.xmax), bounds.setLow(1, box.ymin), bounds.setHigh(1, box.ymax);
  space->as<ob::SE2StateSpace>()->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<SameValidity>(si, *p.space));
  if (checker == Checker::same) si->setMotionValidator(std::make_shared<SameMotion>(si, *p.space));
  si->setup();
  ob::ScopedState<ob::SE2StateSpace> start(space), goal(space);
  // OMPL's SO2 holds [-pi, pi): a heading of 180 degrees is out of its bounds as pi.
  const auto yaw = [](double theta) {
    const double y = std::remainder(theta, 2 * std::numbers::pi);
    return y >= std::numbers::pi ? y - 2 * std::numbers::pi : y;
  };
  start->setXY(p.start.x, p.start.y), start->setYaw(yaw(p.start.theta));
  goal->setXY(p.goal.x, p.goal.y), goal->setYaw(yaw(p.goal.theta));
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal, 1e-9);
  ob::PlannerPtr planner;
  if (rrtstar) {
    auto star = std::make_shared<og::RRTstar>(si);
    star->setRange(p.step);
    star->setGoalBias(0.05);
    planner = star;
  } else {
    auto connect = std::make_shared<og::RRTConnect>(si);
    connect->setRange(p.step);
    planner = connect;
  }
  planner->setProblemDefinition(pdef);
  planner->setup();

  Run run;
  Clock::time_point t0 = Clock::now();
  double first = infinity;
  pdef->setIntermediateSolutionCallback(
      [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost cost) {
        (void)cost;
        if (first == infinity) first = since(t0);
      });
  t0 = Clock::now();
  // RRT* runs to its limit (its length at that time); RRT-Connect stops at its first solution.
  const ob::PlannerStatus status =
      rrtstar ? planner->solve(ob::timedPlannerTerminationCondition(seconds))
              : planner->solve(ob::plannerOrTerminationCondition(ob::timedPlannerTerminationCondition(seconds),
                                                                 ob::exactSolnPlannerTerminationCondition(pdef)));
  const double wall = since(t0);
  if (status != ob::PlannerStatus::EXACT_SOLUTION || !pdef->hasExactSolution()) return run;
  const auto* path = pdef->getSolutionPath()->as<og::PathGeometric>();
  run.solved = true;
  run.seconds = rrtstar ? first : wall;
  run.length = path->length();
  for (std::size_t i = 0; i + 1 < path->getStateCount(); ++i) {
    const CarState a = state_of(path->getState(i)), b = state_of(path->getState(i + 1));
    if (!p.space->motion_is_free(a, b)) {
      run.certified = false;
      if (dense_hit(p, a.pose, b.pose)) run.collides = true;
    }
  }
  return run;
}

// An OMPL run in a child process seeded with `seed`: OMPL 1.5.2's Dubins space asserts on some
// pose pairs (dubinsRSR: "fabs(p * sin(alpha - t) - ca + cb) < 2 * DUBINS_EPS"), which aborts
// the process; the child's abort is counted (aborted) and the race goes on. The parent never
// makes an OMPL object, so each child's RNGs are seeded afresh from `seed`. polyplan's runs are
// children too, so that both sides start alike.
template <class Body>
Run in_child(std::uint32_t seed, Body body) {
  int channel[2];
  if (pipe(channel) != 0) throw std::runtime_error("car_race: pipe failed");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("car_race: fork failed");
  if (child == 0) {
    close(channel[0]);
    ompl::RNG::setSeed(seed);
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const Run run = body();
    const bool written = write(channel[1], &run, sizeof run) == static_cast<ssize_t>(sizeof run);
    _exit(written ? 0 : 1);
  }
  close(channel[1]);
  Run run;
  const bool read_all = read(channel[0], &run, sizeof run) == static_cast<ssize_t>(sizeof run);
  close(channel[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!read_all || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return Run{.aborted = true};
  return run;
}

// ---------------------------------------------------------------------------------------------
// polyplan's planners from the registry.

Run run_polyplan(const CarProblem& p, const std::string& planner, std::uint64_t seed, double seconds) {
  const PlannerEntry<SteeredCar>* entry = planners<SteeredCar>().find(planner);
  OptionValues options{{"time", std::to_string(seconds)}};
  if (planner != "hybrid-astar")
    options.insert(options.end(),
                   {{"seed", std::to_string(seed)}, {"shortcut", "false"}, {"step", std::to_string(p.step)}});
  const auto made = entry->make(p.world, options);
  const Clock::time_point t0 = Clock::now();
  const PlanReport<CarState> report = made->plan(p.world.queries.at(0));
  Run run;
  if (!report.found) return run;
  run.solved = true;
  run.seconds = report.facts.contains(SamplingFacts::first_solution_seconds)
                    ? report.facts.at(SamplingFacts::first_solution_seconds)
                    : since(t0);
  run.length = report.length;
  return run;
}

// ---------------------------------------------------------------------------------------------
// The table.

struct Row {
  std::string planner, checker;
  std::vector<Run> runs;
};

std::string seconds_text(double s) {
  if (s == infinity) return "—";
  char text[32];
  if (s < 1e-3) std::snprintf(text, sizeof text, "%.0f µs", s * 1e6);
  else if (s < 1) std::snprintf(text, sizeof text, "%.1f ms", s * 1e3);
  else std::snprintf(text, sizeof text, "%.2f s", s);
  return text;
}

double median(std::vector<double> v) {
  if (v.empty()) return infinity;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void print_table(const CarProblem& p, const std::vector<Row>& rows) {
  std::cout << "\n### " << p.name << " (" << (p.steering().reverse ? "Reeds–Shepp" : "Dubins") << ", R "
            << p.steering().turning_radius << ", step " << p.step << ")\n\n"
            << "| planner | checker | solved | median first solution | median length | uncertified paths | colliding "
               "paths | aborted |\n"
            << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Row& row : rows) {
    std::size_t solved = 0, uncertified = 0, colliding = 0, aborted = 0;
    std::vector<double> times, lengths;
    for (const Run& r : row.runs) {
      aborted += r.aborted;
      times.push_back(r.seconds);  // unsolved: +infinity, so the median counts them
      if (!r.solved) continue;
      ++solved;
      lengths.push_back(r.length);
      uncertified += !r.certified;
      colliding += r.collides;
    }
    char length[32] = "—";
    if (!lengths.empty()) std::snprintf(length, sizeof length, "%.3f", median(lengths));
    std::cout << "| " << row.planner << " | " << row.checker << " | " << solved << "/" << row.runs.size() << " | "
              << seconds_text(median(times)) << " | " << length << " | " << uncertified << " | " << colliding << " | "
              << aborted << " |\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The car's race: polyplan's car planners against OMPL's on the Dubins and Reeds–Shepp spaces"};
  std::size_t seeds = 20;
  double seconds = 10, length_seconds = 1;
  std::string data = POLYPLAN_DATA_DIR;
  std::vector<std::string> worlds{"car_u_turn", "car_parallel_parking", "car_park", "car_slalom"};
  bool quick = false;
  app.add_option("--seeds", seeds, "seeds per world, planner and checker");
  app.add_option("--seconds", seconds, "time limit of a run to its first solution, seconds");
  app.add_option("--length-seconds", length_seconds, "RRT*'s run time for its length, seconds");
  app.add_option("--worlds", worlds, "car worlds of data/worlds (names without .json)")->delimiter(',');
  app.add_option("--data", data, "polyplan's data directory");
  app.add_flag("--quick", quick, "smoke run: 3 seeds, 1 s limits, 0.2 s RRT*");
  CLI11_PARSE(app, argc, argv);
  if (quick) seeds = 3, seconds = 1, length_seconds = 0.2;

  std::cout
      << "# car_race: " << seeds << " seeds, first solutions within " << seconds << " s, RRT* lengths at "
      << length_seconds
      << " s; polyplan shortcut=false; OMPL runs each in a child process seeded with the seed (ompl::RNG::setSeed)\n";
  for (const std::string& name : worlds) {
    CarProblem p(data + "/worlds/" + name + ".json", name);
    std::vector<Row> rows;
    const auto add = [&](std::string planner, std::string checker, auto run) {
      Row row{std::move(planner), std::move(checker), {}};
      for (std::size_t s = 1; s <= seeds; ++s) row.runs.push_back(run(s));
      std::cerr << name << ": " << row.planner << " (" << row.checker << ") done\n";
      rows.push_back(std::move(row));
    };
    // polyplan's runs too in a child, warmed up alike, so that both sides pay the same for a fresh process.
    const auto ours = [&](std::string planner, double limit) {
      return [&p, planner, limit](std::size_t s) {
        return in_child(static_cast<std::uint32_t>(s), [&] {
          run_polyplan(p, planner, s, 0.005);
          return run_polyplan(p, planner, s, limit);
        });
      };
    };
    add("polyplan hybrid-astar", "certified", ours("hybrid-astar", seconds));
    add("polyplan rrtconnect", "certified", ours("rrtconnect", seconds));
    const auto ompl = [&](bool rrtstar, Checker checker, double limit) {
      return [&p, rrtstar, checker, limit](std::size_t s) {
        return in_child(static_cast<std::uint32_t>(s), [&] {
          run_ompl(p, rrtstar, checker, 0.005);  // warm-up: a fresh process's first solve pays for its start-up
          return run_ompl(p, rrtstar, checker, limit);
        });
      };
    };
    add("OMPL RRTConnect", "same (certified)", ompl(false, Checker::same, seconds));
    add("OMPL RRTConnect", "discrete (default)", ompl(false, Checker::discrete, seconds));
    add("polyplan rrtstar", "certified", ours("rrtstar", length_seconds));
    add("OMPL RRTstar", "same (certified)", ompl(true, Checker::same, length_seconds));
    add("OMPL RRTstar", "discrete (default)", ompl(true, Checker::discrete, length_seconds));
    print_table(p, rows);
  }
  std::cout << "\nRRT* rows: time to its first solution and its length when its run of --length-seconds ends.\n";
  return 0;
}
