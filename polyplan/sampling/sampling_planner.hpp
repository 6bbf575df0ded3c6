#pragma once
// What the sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) share, over any
// SamplingSpace (sampling/sampling_space.hpp): the limits every one takes (seed, time, iterations,
// shortcutting), the configurations they place with their nearest-neighbour index, and one plan()
// that checks the query, runs the planner's own search within the limits, shortcuts the path with
// certified motions, certifies the path once more and reports the shared facts:
//   samples                 configurations drawn (free or not)
//   motions_checked         motions the space certified or refused
//   iterations              the planner's own steps (samples for the roadmaps, extensions for trees)
//   stopped_by              "solution", "iteration limit" or "time limit"
//   first_solution_seconds  when the first path was found (the query's clock)
//   raw_length              the first path's length before shortcutting (length: the one returned)
//   roadmap.kind (the planner's name), seed, query_seconds
// A planner derives from SamplingPlanner<Space>, writes solve(), and registers one entry per space
// (registry/polygon_planners.cpp, registry/arm_planners.cpp) with the space's factory.
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/sampling/nearest_neighbours.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace polyplan {

struct SamplingLimits {
  std::uint64_t seed = 1;
  double time = 10;                 // seconds per query (wall clock)
  std::size_t iterations = 100000;  // per query: samples (roadmaps) or extensions (trees)
  bool shortcut = true;             // shorten the path found with certified shortcuts
};

// The options "seed", "time", "iterations" and "shortcut" of a planner whose options struct
// derives from SamplingLimits (the planner's constructor refuses a time or iteration limit that
// is not positive).
template <class Options>
OptionTable<Options>& add_sampling_options(OptionTable<Options>& table) {
  static_assert(std::is_base_of_v<SamplingLimits, Options>);
  return table.add("seed", static_cast<std::uint64_t Options::*>(&SamplingLimits::seed), "the random numbers' seed: one seed, one path")
      .add("time", static_cast<double Options::*>(&SamplingLimits::time), "time limit per query, seconds")
      .add("iterations", static_cast<std::size_t Options::*>(&SamplingLimits::iterations),
           "iteration limit per query: samples (prm, lazyprm) or extensions (trees)")
      .add("shortcut", static_cast<bool Options::*>(&SamplingLimits::shortcut),
           "shorten the path with certified shortcuts (raw_length keeps the first path's length)");
}

// Configurations a planner has placed (tree nodes, roadmap milestones), each with its coordinates
// in a nearest-neighbour index; ids 0, 1, 2, ... in order.
template <class Space>
class SampledConfigurations {
 public:
  using Configuration = typename Space::Configuration;

  explicit SampledConfigurations(const SamplingSpace<Space>& space) : index_(space.dimension(), space.metric()) {}

  std::size_t add(Configuration configuration, std::span<const double> coordinates) {
    configurations_.push_back(std::move(configuration));
    return index_.add(coordinates);
  }
  std::size_t size() const { return configurations_.size(); }
  const Configuration& operator[](std::size_t id) const { return configurations_[id]; }
  std::span<const double> coordinates(std::size_t id) const { return index_.point(id); }
  const NearestNeighbours& neighbours() const { return index_; }
  const std::vector<Configuration>& all() const { return configurations_; }

 private:
  std::vector<Configuration> configurations_;
  NearestNeighbours index_;
};

// A tree of configurations (rrt, rrtconnect, rrtstar): each node but the root joined to its
// parent by a certified motion.
template <class Space>
class SamplingTree {
 public:
  using Configuration = typename Space::Configuration;
  static constexpr std::size_t root = 0;

  SamplingTree(const SamplingSpace<Space>& space, const Configuration& root_configuration) : nodes_(space) {
    std::vector<double> coordinates(space.dimension());
    space.coordinates(root_configuration, coordinates);
    add(root_configuration, coordinates, root);
  }

  std::size_t add(Configuration configuration, std::span<const double> coordinates, std::size_t parent) {
    parents_.push_back(parent);
    return nodes_.add(std::move(configuration), coordinates);
  }
  std::size_t size() const { return nodes_.size(); }
  const SampledConfigurations<Space>& nodes() const { return nodes_; }
  std::size_t parent(std::size_t id) const { return parents_[id]; }
  void set_parent(std::size_t id, std::size_t parent) { parents_[id] = parent; }

  // The configurations from the root to `id`.
  std::vector<Configuration> path_from_root(std::size_t id) const {
    std::vector<Configuration> path{nodes_[id]};
    for (; id != root; id = parents_[id]) path.push_back(nodes_[parents_[id]]);
    return {path.rbegin(), path.rend()};
  }
  // The picture of trees: their nodes, and an edge from each node to its parent.
  static std::shared_ptr<const PlanGraph<Configuration>> picture(std::initializer_list<const SamplingTree*> trees) {
    auto graph = std::make_shared<PlanGraph<Configuration>>();
    graph->kind = "tree";
    for (const SamplingTree* tree : trees) {
      const std::size_t offset = graph->vertices.size();
      graph->vertices.insert(graph->vertices.end(), tree->nodes_.all().begin(), tree->nodes_.all().end());
      for (std::size_t id = 1; id < tree->size(); ++id) graph->edges.emplace_back(offset + tree->parents_[id], offset + id);
    }
    return graph;
  }

 private:
  SampledConfigurations<Space> nodes_;
  std::vector<std::size_t> parents_;
};

// The limits of one query as it runs.
class SamplingBudget {
 public:
  explicit SamplingBudget(const SamplingLimits& limits)
      : seconds_(limits.time), iterations_(limits.iterations) {}

  // Counts an iteration; false (and nothing counted) once the iteration or time limit is reached.
  bool next() {
    if (spent()) return false;
    ++used_;
    return true;
  }
  bool spent() {
    if (used_ >= iterations_) out_of_iterations_ = true;
    else if (running_.seconds() >= seconds_) timed_out_ = true;
    return out_of_iterations_ || timed_out_;
  }
  std::size_t used() const { return used_; }
  double seconds() const { return running_.seconds(); }
  // "the time limit (10 s)" or "the iteration limit (100000)": what stopped the query.
  std::string limit_reached() const;
  // "time limit", "iteration limit", or "solution" when the planner stopped before either (a
  // query stopped by the time limit may differ from run to run; the others never do).
  std::string stopped_by() const { return timed_out_ ? "time limit" : out_of_iterations_ ? "iteration limit" : "solution"; }

 private:
  Stopwatch running_;
  double seconds_;
  std::size_t iterations_;
  std::size_t used_ = 0;
  bool timed_out_ = false, out_of_iterations_ = false;
};

// A solution's length when it was found: RRT*'s anytime progress (first, then each improvement),
// read by the benchmarks' cost-versus-time curves.
struct SolutionImprovement {
  double seconds = 0;
  double length = 0;
};

template <class Space>
class SamplingPlanner : public Planner<Space> {
 public:
  using Configuration = typename Space::Configuration;
  using Query = typename Space::Query;

  PlanReport<Configuration> plan(const Query& query, const QueryOptions& options = {}) final;

  // The last query's solutions, in the order found (empty when none).
  const std::vector<SolutionImprovement>& improvements() const { return improvements_; }

 protected:
  // `name`: the registry's, reported as roadmap.kind.
  SamplingPlanner(std::string name, std::unique_ptr<SamplingSpace<Space>> space, SamplingLimits limits);

  // What solve() returns: a path from the query's start to its goal (exactly those
  // configurations; the start alone when it is the goal) whose consecutive configurations are
  // joined by certified motions, or why there is none; the picture's graph when `record`.
  struct Attempt {
    std::vector<Configuration> path;
    std::string why_not;
    std::shared_ptr<const PlanGraph<Configuration>> graph;
  };
  // The planner's own search within the budget. Facts particular to it go in `facts`; a solution
  // is announced with found() as soon as it exists (found() times the first and every better one).
  virtual Attempt solve(const Query& query, SamplingBudget& budget, Facts& facts, bool record) = 0;

  // For solve(): the counted operations and the space.
  SamplingSpace<Space>& space() { return *space_; }
  const SamplingSpace<Space>& space() const { return *space_; }
  SamplingRandom& random() { return random_; }
  // Draws a configuration uniformly (counted as a sample); its coordinates into `coordinates`.
  Configuration draw(std::span<double> coordinates);
  bool state_free(const Configuration& c) { return space_->is_free(c); }
  bool motion_free(const Configuration& from, const Configuration& to) {
    ++motions_checked_;
    return space_->motion_is_free(from, to);
  }
  double distance(std::span<const double> a, std::span<const double> b) const {
    return sampling_distance(space_->metric(), a, b);
  }
  // What a tree grows toward: the goal itself with probability `goal_bias`, otherwise a drawn
  // configuration (its coordinates into `drawn_at`).
  struct Sample {
    Configuration configuration;
    std::span<const double> at;
    bool is_goal = false;
  };
  Sample goal_biased(const Configuration& goal, std::span<const double> goal_at, double goal_bias, std::span<double> drawn_at) {
    if (uniform01(random_) < goal_bias) return {goal, goal_at, true};
    Configuration drawn = draw(drawn_at);
    return {std::move(drawn), drawn_at, false};
  }
  // One extension of `tree` toward `target`: from its nearest node, `target` itself when it is
  // within `step` (or step is 0: all the way), otherwise the configuration `step` along the way;
  // the coordinates of where it ends into `out`. `stays`: the nearest node is there already.
  struct Step {
    std::size_t from = 0;
    Configuration to;
    bool reaches_target = false;
    bool stays = false;
  };
  Step step_toward(const SamplingTree<Space>& tree, const Configuration& target, std::span<const double> target_at, double step,
                   std::span<double> out) const {
    const std::size_t from = tree.nodes().neighbours().nearest(target_at);
    const auto from_at = tree.nodes().coordinates(from);
    const double d = distance(from_at, target_at);
    if (step <= 0 || d <= step) {
      std::copy(target_at.begin(), target_at.end(), out.begin());
      return {from, target, true, d == 0};
    }
    sampling_interpolate(space_->metric(), from_at, target_at, step / d, out);
    return {from, space_->configuration(out), false, distance(from_at, out) == 0};
  }
  // The length of a path of configurations in the space's metric.
  double length(const std::vector<Configuration>& path) const;
  void found(const SamplingBudget& budget, double length) { improvements_.push_back({budget.seconds(), length}); }

 private:
  // Shortcuts between random points of the path, each new motion certified (the .cpp says how).
  std::vector<Configuration> shortcut(std::vector<Configuration> path);

  std::string name_;
  std::unique_ptr<SamplingSpace<Space>> space_;
  SamplingLimits limits_;
  SamplingRandom random_;
  std::size_t samples_ = 0, motions_checked_ = 0;
  std::vector<SolutionImprovement> improvements_;
};

// A planner's registry entry for one space: `make(space, options)` builds it on the space that
// `make_space` makes of the problem. The
// sampling planners' sources define their entries with this (one per space, explicitly
// instantiated for TranslatingRobot and PlanarArm).
template <class Space, class Options, class Make>
PlannerEntry<Space> make_sampling_entry(std::string name, std::string description, OptionTable<Options> table,
                                        SamplingSpaceFactory<Space> make_space, Make make) {
  return make_planner_entry<Space, Options>(
      std::move(name), std::move(description), std::move(table),
      [make_space = std::move(make_space), make](const typename Space::Problem& problem, const Options& options)
          -> std::unique_ptr<Planner<Space>> { return make(make_space(problem), options); });
}

}  // namespace polyplan
