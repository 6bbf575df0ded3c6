#pragma once
// What the sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) share, over any
// SamplingSpace (sampling/sampling_space.hpp): the limits every one takes (seed, time, iterations,
// shortcutting), the configurations they place with their nearest-neighbour index, and one plan()
// that checks the query, asks the space for the query's goals (SamplingSpace::goals: one, or a set
// of which the path must reach any one), runs the planner's own search within the limits, shortcuts
// the path with certified motions, certifies the path once more and reports the shared facts:
//   samples                 configurations drawn (free or not)
//   motions_checked         motions the space certified or refused
//   iterations              the planner's own steps (samples for the roadmaps, extensions for trees)
//   stopped_by              "solution", "iteration limit" or "time limit"
//   first_solution_seconds  when the first path was found (the query's clock)
//   raw_length              the first path's length before shortcutting (length: the one returned)
//   roadmap.kind (the planner's name), seed, query_seconds
//   goal.candidates         how many goals, where there are several (never with one goal, so that a
//                           query's answer is what it was before goal sets)
//   goal.reached            which of them the path ends at: its 0-based index in goals()
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
#include <stdexcept>
#include <string>
#include <string_view>
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
  return table
      .add("seed", static_cast<std::uint64_t Options::*>(&SamplingLimits::seed),
           "the random numbers' seed: one seed, one path")
      .add("time", static_cast<double Options::*>(&SamplingLimits::time), "time limit per query, seconds", above(0))
      .add("iterations", static_cast<std::size_t Options::*>(&SamplingLimits::iterations),
           "iteration limit per query: samples (prm, lazyprm) or extensions (trees)", at_least(1))
      .add("shortcut", static_cast<bool Options::*>(&SamplingLimits::shortcut),
           "shorten the path with certified shortcuts (raw_length keeps the first path's length)");
}

// The option "roadmap-size" of prm and lazyprm (Options::roadmap_size): the K-PRM built before any
// query (sampling/detail/roadmap_planner.hpp).
template <class Options>
OptionTable<Options>& add_roadmap_size_option(OptionTable<Options>& table) {
  return table.add("roadmap-size", &Options::roadmap_size,
                   "build a roadmap of this many free samples before any query and answer every query on it, "
                   "not growing it (0: grow it as queries need)",
                   at_least(0));
}

// Which way a distance runs between a placed configuration and coordinates asked about: the
// motion from the placed one to them (a tree grown from its root), or from them to the placed one
// (a tree grown toward its root: RRT-Connect's goal tree). The same in a symmetric space.
enum class Toward { asked, placed };

// Configurations a planner has placed (tree nodes, roadmap milestones), each with its coordinates
// in a nearest-neighbour index; ids 0, 1, 2, ... in order. Nearest means by the space's distance():
// when that is not the index's metric, the index's (a lower bound both ways) gives candidates —
// the k nearest by the bound fix a radius r, the true k-th distance among them, and every
// configuration truly within r is within r by the bound — so each answer is the true one.
template <class Space>
class SampledConfigurations {
 public:
  using Configuration = typename Space::Configuration;

  explicit SampledConfigurations(const SamplingSpace<Space>& space)
      : space_(&space), dimension_(space.dimension()), index_(space.index_dimension(), space.metric()) {}

  // `region`: what its clearance proves, when measured already (otherwise measured when first asked).
  std::size_t add(Configuration configuration, std::span<const double> coordinates,
                  std::shared_ptr<const FreeRegion> region = nullptr) {
    configurations_.push_back(std::move(configuration));
    regions_.push_back(std::move(region));
    coordinates_.insert(coordinates_.end(), coordinates.begin(),
                        coordinates.begin() + static_cast<std::ptrdiff_t>(dimension_));
    return index_.add(coordinates.first(index_.dimension()));
  }
  std::size_t size() const { return configurations_.size(); }
  const Configuration& operator[](std::size_t id) const { return configurations_[id]; }
  std::span<const double> coordinates(std::size_t id) const {
    return std::span(coordinates_).subspan(id * dimension_, dimension_);
  }
  const std::vector<Configuration>& all() const { return configurations_; }
  // Configuration `id`'s free region (SamplingSpace::free_region), kept once measured: the
  // planner's memory of what the node's clearance proves, filled in as motions ask for it.
  std::shared_ptr<const FreeRegion>& region(std::size_t id) const { return regions_[id]; }

  // The space's distance between configuration `id` and `at`, the way `toward` says.
  double distance(std::size_t id, std::span<const double> at, Toward toward = Toward::asked) const {
    return toward == Toward::asked ? space_->distance(coordinates(id), at) : space_->distance(at, coordinates(id));
  }
  // The id of a configuration nearest to `at`. Throws std::logic_error when there is none.
  std::size_t nearest(std::span<const double> at, Toward toward = Toward::asked) const;
  // The min(k, size()) nearest to `at`, nearest first, into `out` (cleared).
  void nearest(std::span<const double> at, std::size_t k, std::vector<std::size_t>& out,
               Toward toward = Toward::asked) const;
  // Every configuration within `radius` of `at` (distance <= radius), nearest first, into `out`.
  void within(std::span<const double> at, double radius, std::vector<std::size_t>& out,
              Toward toward = Toward::asked) const;

 private:
  // A distance grown past the rounding that may put a lower bound, computed otherwise, above it.
  static double widened(double d) { return d + 1e-9 * (1 + d); }
  // `ids` ordered by their true distance to `at`, the first `keep` (all by default) kept.
  void by_distance(std::span<const double> at, std::vector<std::size_t>& ids, Toward toward,
                   std::size_t keep = SIZE_MAX) const;  // SIZE_MAX: <cstdint>

  const SamplingSpace<Space>* space_;
  std::size_t dimension_;
  std::vector<Configuration> configurations_;
  std::vector<double> coordinates_;  // configuration i's at [i·dimension, (i + 1)·dimension)
  mutable std::vector<std::shared_ptr<const FreeRegion>> regions_;
  NearestNeighbours index_;
  mutable std::vector<std::size_t> candidates_;
  mutable std::vector<std::pair<double, std::size_t>> ranked_;
};

template <class Space>
void SampledConfigurations<Space>::by_distance(std::span<const double> at, std::vector<std::size_t>& ids, Toward toward,
                                               std::size_t keep) const {
  ranked_.clear();
  for (std::size_t id : ids) ranked_.emplace_back(distance(id, at, toward), id);
  keep = std::min(keep, ranked_.size());
  std::partial_sort(ranked_.begin(), ranked_.begin() + static_cast<std::ptrdiff_t>(keep), ranked_.end());
  ids.clear();
  for (std::size_t i = 0; i < keep; ++i) ids.push_back(ranked_[i].second);
}

template <class Space>
void SampledConfigurations<Space>::nearest(std::span<const double> at, std::size_t k, std::vector<std::size_t>& out,
                                           Toward toward) const {
  const auto key = at.first(index_.dimension());
  index_.nearest(key, k, out);
  if (space_->distance_is_metric() || out.empty()) return;
  by_distance(at, out, toward);
  // ranked_ holds the k best so far (distance, id), nearest first. Every other candidate lies
  // within the k-th distance by the index's bound (widened past rounding: the bounds and the
  // distance are computed differently), nearest by the bound first, so the walk stops at the
  // first one the bound puts beyond the k-th.
  index_.within(key, widened(ranked_[out.size() - 1].first), candidates_);
  const std::size_t first_k = out.size();
  for (std::size_t id : candidates_) {
    const double kth = ranked_[first_k - 1].first;
    const auto placed_at = coordinates(id);
    if (sampling_distance(space_->metric(), placed_at.first(key.size()), key) > widened(kth)) break;
    if (std::find(out.begin(), out.end(), id) != out.end()) continue;
    const double bound =
        toward == Toward::asked ? space_->distance_bound(placed_at, at) : space_->distance_bound(at, placed_at);
    if (bound > widened(kth)) continue;
    const double d = distance(id, at, toward);
    if (d >= kth) continue;
    ranked_[first_k - 1] = {d, id};  // the worst gives way; insertion keeps the order
    for (std::size_t i = first_k - 1; i > 0 && ranked_[i] < ranked_[i - 1]; --i) std::swap(ranked_[i], ranked_[i - 1]);
  }
  out.clear();
  for (std::size_t i = 0; i < first_k; ++i) out.push_back(ranked_[i].second);
}

template <class Space>
std::size_t SampledConfigurations<Space>::nearest(std::span<const double> at, Toward toward) const {
  if (space_->distance_is_metric()) return index_.nearest(at.first(index_.dimension()));
  std::vector<std::size_t> one;
  nearest(at, 1, one, toward);
  if (one.empty()) throw std::logic_error("nearest configuration asked of none");
  return one.front();
}

template <class Space>
void SampledConfigurations<Space>::within(std::span<const double> at, double radius, std::vector<std::size_t>& out,
                                          Toward toward) const {
  if (space_->distance_is_metric()) return index_.within(at.first(index_.dimension()), radius, out);
  index_.within(at.first(index_.dimension()), widened(radius), out);
  ranked_.clear();
  for (std::size_t id : out) {
    const auto placed_at = coordinates(id);
    const double bound =
        toward == Toward::asked ? space_->distance_bound(placed_at, at) : space_->distance_bound(at, placed_at);
    if (bound > widened(radius)) continue;
    if (const double d = distance(id, at, toward); d <= radius) ranked_.emplace_back(d, id);
  }
  std::sort(ranked_.begin(), ranked_.end());
  out.clear();
  for (const auto& [d, id] : ranked_) out.push_back(id);
}

// A tree of configurations (rrt, rrtconnect, rrtstar): each node but a root joined to its
// parent by a certified motion — from the parent to the node when the tree grows from its root
// (Toward::asked: distances run from nodes to what the tree extends toward), from the node to its
// parent when it grows toward its root (Toward::placed: RRT-Connect's goal tree). It may be a
// forest of several roots (RRT-Connect's goal tree, rooted at every goal): a root is the node that
// is its own parent.
template <class Space>
class SamplingTree {
 public:
  using Configuration = typename Space::Configuration;
  static constexpr std::size_t root = 0;  // the first root

  SamplingTree(const SamplingSpace<Space>& space, const Configuration& root_configuration,
               Toward growth = Toward::asked)
      : SamplingTree(space, std::vector<Configuration>{root_configuration}, growth) {}
  // Roots i = 0, 1, ... at roots[i], in that order.
  SamplingTree(const SamplingSpace<Space>& space, const std::vector<Configuration>& roots,
               Toward growth = Toward::asked)
      : nodes_(space), growth_(growth) {
    std::vector<double> coordinates(space.dimension());
    for (const Configuration& root_configuration : roots) {
      space.coordinates(root_configuration, coordinates);
      add(root_configuration, coordinates, size());
    }
  }

  std::size_t add(Configuration configuration, std::span<const double> coordinates, std::size_t parent,
                  std::shared_ptr<const FreeRegion> region = nullptr) {
    parents_.push_back(parent);
    return nodes_.add(std::move(configuration), coordinates, std::move(region));
  }
  std::size_t size() const { return nodes_.size(); }
  const SampledConfigurations<Space>& nodes() const { return nodes_; }
  Toward growth() const { return growth_; }
  std::size_t parent(std::size_t id) const { return parents_[id]; }
  void set_parent(std::size_t id, std::size_t parent) { parents_[id] = parent; }

  bool is_root(std::size_t id) const { return parents_[id] == id; }

  // The configurations from the root of `id`'s tree to `id`.
  std::vector<Configuration> path_from_root(std::size_t id) const {
    std::vector<Configuration> path{nodes_[id]};
    for (; !is_root(id); id = parents_[id]) path.push_back(nodes_[parents_[id]]);
    return {path.rbegin(), path.rend()};
  }
  // The picture of trees: their nodes, and an edge for each node's motion, from where it starts
  // to where it ends (parent to node, or node to parent in a tree grown toward its root).
  static std::shared_ptr<const PlanGraph<Configuration>> picture(std::initializer_list<const SamplingTree*> trees) {
    auto graph = std::make_shared<PlanGraph<Configuration>>();
    graph->kind = "tree";
    for (const SamplingTree* tree : trees) {
      const std::size_t offset = graph->vertices.size();
      graph->vertices.insert(graph->vertices.end(), tree->nodes_.all().begin(), tree->nodes_.all().end());
      for (std::size_t id = 0; id < tree->size(); ++id) {
        if (tree->is_root(id)) continue;
        const std::size_t parent = offset + tree->parents_[id], node = offset + id;
        if (tree->growth_ == Toward::asked) graph->edges.emplace_back(parent, node);
        else graph->edges.emplace_back(node, parent);
      }
    }
    return graph;
  }

 private:
  SampledConfigurations<Space> nodes_;
  Toward growth_;
  std::vector<std::size_t> parents_;
};

// The limits of one query as it runs.
class SamplingBudget {
 public:
  explicit SamplingBudget(const SamplingLimits& limits) : seconds_(limits.time), iterations_(limits.iterations) {}

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
  // Whether the time limit has passed, counting nothing: asked within an iteration whose work may
  // stop part way (RRT*'s choice of parent and rewiring, a lazy roadmap's certification, PRM's
  // joins) and by the work after the search (shortcutting), so that the query ends at its limit.
  // A cut counts as the time limit's stop: the answer then depends on the machine's speed.
  bool out_of_time() {
    if (running_.seconds() >= seconds_) timed_out_ = true;
    return timed_out_;
  }
  std::size_t used() const { return used_; }
  double seconds() const { return running_.seconds(); }
  // "the time limit (10 s)" or "the iteration limit (100000)": what stopped the query.
  std::string limit_reached() const;
  // "time limit", "iteration limit", or "solution" when the planner stopped before either (a
  // query stopped by the time limit may differ from run to run; the others never do, nor do the
  // queries after a cut one, which draw their own random streams — but a roadmap that a cut query
  // grew is the roadmap the next query finds).
  std::string stopped_by() const {
    return timed_out_ ? "time limit" : out_of_iterations_ ? "iteration limit" : "solution";
  }

 private:
  Stopwatch running_;
  double seconds_;
  std::size_t iterations_;
  std::size_t used_ = 0;
  bool timed_out_ = false, out_of_iterations_ = false;
};

template <class Space>
class SamplingPlanner : public Planner<Space> {
 public:
  using Configuration = typename Space::Configuration;
  using Query = typename Space::Query;

  PlanReport<Configuration> plan(const Query& query, const QueryOptions& options = {}) final;

  // The last query's solutions, in the order found (empty when none), before shortcutting (the
  // report's improvements add the shortcut path).
  const std::vector<SolutionImprovement>& improvements() const { return improvements_; }

 protected:
  // `name`: the registry's, reported as roadmap.kind.
  SamplingPlanner(std::string name, std::unique_ptr<SamplingSpace<Space>> space, SamplingLimits limits);

  // What solve() returns: a path from the query's start to one of its goals (exactly those
  // configurations; the start alone when it is a goal) whose consecutive configurations are
  // joined by certified motions, or why there is none; the picture's graph when `record`.
  struct Attempt {
    std::vector<Configuration> path;
    std::string why_not;
    std::shared_ptr<const PlanGraph<Configuration>> graph;
    // Why there is no path: a limit reached, or not_found (a prebuilt roadmap that does not join).
    PlanStatus status = PlanStatus::limit;
  };
  // The planner's own search within the budget, from the query's start to any one of `goals` (the
  // space's goals(query), never empty; the nearest one the planner can reach). Facts particular to
  // it go in `facts`; a solution is announced with found() as soon as it exists (found() times the
  // first and every better one).
  virtual Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget,
                        Facts& facts, bool record) = 0;

  // A `T` made of `args` for solve()'s search (its trees), kept until the planner's next query
  // begins or the planner ends: freeing a tree of tens of thousands of nodes takes tens of
  // milliseconds, which would run the query past its time limit.
  template <class T, class... Args>
  T& kept(Args&&... args) {
    auto made = std::make_shared<T>(std::forward<Args>(args)...);
    T& value = *made;
    kept_.push_back(std::move(made));
    return value;
  }

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
  double distance(std::span<const double> a, std::span<const double> b) const { return space_->distance(a, b); }
  // Which of `goals` `configuration` is (the first equal to it), if any.
  static std::optional<std::size_t> goal_index(const std::vector<Configuration>& goals,
                                               const Configuration& configuration) {
    const auto found = std::find(goals.begin(), goals.end(), configuration);
    if (found == goals.end()) return std::nullopt;
    return static_cast<std::size_t>(found - goals.begin());
  }
  // The coordinates of each configuration (a query's goals, for goal_biased).
  std::vector<std::vector<double>> coordinates_of(const std::vector<Configuration>& configurations) const;
  // What a tree grows toward: with probability `goal_bias` one of the goals (uniformly; `goals_at`:
  // their coordinates), otherwise a drawn configuration (its coordinates into `drawn_at`).
  struct Sample {
    Configuration configuration;
    std::span<const double> at;
    std::optional<std::size_t> goal;  // which goal it is, if it is one
  };
  Sample goal_biased(const std::vector<Configuration>& goals, const std::vector<std::vector<double>>& goals_at,
                     double goal_bias, std::span<double> drawn_at);
  // One extension of `tree` toward `target`: from its nearest node, `target` itself when it is
  // within `step` (or step is 0: all the way), otherwise the configuration `step` along the way
  // (in a tree grown toward its root: `step` before the node on the motion from `target` to it);
  // the coordinates of where it ends into `out`. `stays`: the nearest node is there already.
  struct Step {
    std::size_t from = 0;
    Configuration to;
    bool reaches_target = false;
    bool stays = false;
  };
  Step step_toward(const SamplingTree<Space>& tree, const Configuration& target, std::span<const double> target_at,
                   double step, std::span<double> out) const {
    const Toward toward = tree.growth();
    const std::size_t from = tree.nodes().nearest(target_at, toward);
    const auto from_at = tree.nodes().coordinates(from);
    const double d = toward == Toward::asked ? space_->steer(from_at, target_at, step, out)
                                             : space_->steer(target_at, from_at, step, out, SteerFrom::end);
    if (step <= 0 || d <= step) return {from, target, true, d == 0};
    return {from, space_->configuration(out), false, tree.nodes().distance(from, out, toward) == 0};
  }
  // The motion between placed configurations a → b of `nodes`, with what their free regions
  // prove (each measured when first asked and kept with the node). Certified and counted.
  bool motion_free(const SampledConfigurations<Space>& nodes, std::size_t a, std::size_t b) {
    ++motions_checked_;
    return space_->motion_is_free_between(nodes[a], nodes[b], region_of(nodes, a), region_of(nodes, b));
  }
  // The motion between placed `a` and `c`, not placed yet: a → c, or c → a when `reverse`. c's free
  // region is measured into `c_region` unless it holds it already, to be placed with c; when the
  // space keeps regions and c is not free, the motion is refused with nothing more measured.
  // Certified and counted.
  bool motion_free(const SampledConfigurations<Space>& nodes, std::size_t a, const Configuration& c,
                   std::shared_ptr<const FreeRegion>& c_region, bool reverse = false) {
    ++motions_checked_;
    if (space_->keeps_free_regions() && !c_region && !(c_region = space_->free_region(c))) return false;
    const FreeRegion* a_region = region_of(nodes, a);
    return reverse ? space_->motion_is_free_between(c, nodes[a], c_region.get(), a_region)
                   : space_->motion_is_free_between(nodes[a], c, a_region, c_region.get());
  }
  // The motion that joins a tree's node `from` and a configuration `to` grown from it: from → to,
  // or to → from in a tree grown toward its root; `to_region` as above. Certified and counted.
  bool motion_free(const SamplingTree<Space>& tree, std::size_t from, const Configuration& to,
                   std::shared_ptr<const FreeRegion>& to_region) {
    return motion_free(tree.nodes(), from, to, to_region, tree.growth() == Toward::placed);
  }
  // A roadmap's edge between placed a and b: a → b certified, and b → a too in a space that is not
  // symmetric (the edge serves either way). Counted.
  bool edge_free(const SampledConfigurations<Space>& nodes, std::size_t a, std::size_t b) {
    return motion_free(nodes, a, b) && (space_->symmetric() || motion_free(nodes, b, a));
  }
  // The same between placed `a` and `c`, not placed (a query's end joined to a prebuilt roadmap).
  bool edge_free(const SampledConfigurations<Space>& nodes, std::size_t a, const Configuration& c,
                 std::shared_ptr<const FreeRegion>& c_region) {
    return motion_free(nodes, a, c, c_region) && (space_->symmetric() || motion_free(nodes, a, c, c_region, true));
  }
  // Seeds random() with the stream of the seed, the planner's name, `ordinal` and `purpose` (the
  // text mixed in after the name; none for a query's stream, so that each seed's paths stay what
  // they were): one stream on every machine.
  void seed_stream(std::uint64_t ordinal, std::string_view purpose = {});
  // The length of a path of configurations in the space's metric.
  double length(const std::vector<Configuration>& path) const;
  void found(const SamplingBudget& budget, double length) { improvements_.push_back({budget.seconds(), length}); }

 private:
  // Shortcuts between random points of the path, each new motion certified (the .cpp says how),
  // until the budget's time runs out.
  std::vector<Configuration> shortcut(std::vector<Configuration> path, SamplingBudget& budget);
  // Placed configuration `id`'s free region, measured on first asking; null when the space keeps
  // none.
  const FreeRegion* region_of(const SampledConfigurations<Space>& nodes, std::size_t id) {
    if (!space_->keeps_free_regions()) return nullptr;
    std::shared_ptr<const FreeRegion>& region = nodes.region(id);
    if (!region) region = space_->free_region(nodes[id]);
    return region.get();
  }

  std::string name_;
  std::unique_ptr<SamplingSpace<Space>> space_;
  SamplingLimits limits_;
  SamplingRandom random_;
  std::uint64_t queries_asked_ = 0;  // the ordinal of the next query: it picks the query's random stream
  std::size_t samples_ = 0, motions_checked_ = 0;
  std::vector<SolutionImprovement> improvements_;
  std::vector<std::shared_ptr<void>> kept_;  // kept(): freed as the next query begins, before its clock starts
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
