#pragma once
// What the sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) know of a configuration
// space, and nothing more: how to sample it, how far apart two configurations are and how to steer
// between them (on coordinates, by the space's metric), whether a configuration is free, and
// whether the motion between two is free — certified, never sampled (docs/design.md). Three spaces
// implement it: a translating robot in a polygon world (sampling/polygon_sampling_space.hpp: exact
// positions, the exact segment test), a planar arm (arm/arm_sampling_space.hpp: joint angles on
// the torus, conservative advancement) and a steered car (car/car_sampling_space.hpp: poses joined
// by the car's shortest curves, whose length is the distance — not a metric of coordinates, and
// not symmetric for a car that cannot reverse).
//
// A configuration has coordinates (doubles) on which distances, nearest neighbours and steering
// are computed; the configuration itself (an exact point, joint angles) is what the motion test
// and the returned path use. So the query's exact start and goal stay exact in the path even when
// their coordinates are rounded.
#include <polyplan/geometry/angles.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace polyplan {

// How coordinates are measured and joined. The motion a space certifies between two
// configurations is the one sampling_interpolate traces, so steering by a fraction of the way
// lands on that motion.
enum class SamplingMetric {
  euclidean,  // √Σ (a_i − b_i)², straight segments
  torus,      // Σ_i the short way round from a_i to b_i (angles.hpp: a half turn counts as +π), every
              // coordinate turning at a constant rate: the arm's path length and its motions
};

inline double sampling_distance(SamplingMetric metric, std::span<const double> a, std::span<const double> b) {
  double sum = 0;
  if (metric == SamplingMetric::euclidean) {
    for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum);
  }
  for (std::size_t i = 0; i < a.size(); ++i) sum += angular_distance(a[i], b[i]);
  return sum;
}

// The point a fraction t ∈ [0, 1] of the way from a to b, into `out` (torus coordinates normalised).
inline void sampling_interpolate(SamplingMetric metric, std::span<const double> a, std::span<const double> b, double t,
                                 std::span<double> out) {
  for (std::size_t i = 0; i < a.size(); ++i)
    out[i] = metric == SamplingMetric::euclidean ? a[i] + t * (b[i] - a[i])
                                                 : normalize_angle(a[i] + t * signed_angle_difference(a[i], b[i]));
}

// Which end steering starts from (SamplingSpace::steer).
enum class SteerFrom { start, end };

// Why (x, y) is outside the box [xmin, xmax] × [ymin, ymax], or nullopt: the spaces' outside().
inline std::optional<std::string> outside_box(double x, double y, double xmin, double ymin, double xmax, double ymax) {
  if (x >= xmin && x <= xmax && y >= ymin && y <= ymax) return std::nullopt;
  char text[200];
  std::snprintf(text, sizeof text, "(%.10g, %.10g) is outside the sampling box [%.10g, %.10g] x [%.10g, %.10g]", x, y,
                xmin, xmax, ymin, ymax);
  return std::string(text);
}

// The planners' random numbers: a 64-bit Mersenne twister (defined by the standard bit for bit),
// made into doubles here rather than by std::uniform_real_distribution (whose results differ
// between standard libraries), so that one seed gives one path everywhere.
using SamplingRandom = std::mt19937_64;
inline double uniform01(SamplingRandom& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }  // [0, 1)

// What a free configuration's clearance proves about the motions that leave or reach it: a region
// around it that a motion may cross with no new check (arms: its clearances, arm_motion.hpp). Opaque
// to the planners, which keep one per placed configuration (SampledConfigurations) and hand the
// ends' back to SamplingSpace::motion_is_free_between. docs/certification.md, "Reused clearances".
struct FreeRegion {
  virtual ~FreeRegion() = default;
};

template <class Space>
class SamplingSpace {
 public:
  using Configuration = typename Space::Configuration;
  using Query = typename Space::Query;

  virtual ~SamplingSpace() = default;

  virtual std::size_t dimension() const = 0;
  // The metric of the nearest-neighbour index, on the first index_dimension() coordinates. For a
  // space whose distance() is its own (distance_is_metric() false), this metric must bound
  // distance() from below both ways, so that the index finds the true nearest (sampling_planner.hpp).
  virtual SamplingMetric metric() const = 0;
  virtual std::size_t index_dimension() const { return dimension(); }
  virtual bool distance_is_metric() const { return true; }
  // Whether distance(a, b) = distance(b, a) and the motion b → a is a → b's reversed: then a
  // roadmap's edge serves both ways once certified one way.
  virtual bool symmetric() const { return true; }
  // The length of the motion a → b, and the coordinates a fraction t ∈ [0, 1] of the way along it
  // (the metric's and sampling_interpolate's by default).
  virtual double distance(std::span<const double> a, std::span<const double> b) const {
    return sampling_distance(metric(), a, b);
  }
  // A lower bound on distance(a, b) cheaper than it, at least the index metric's (which it is by
  // default): nearest-neighbour queries skip what it rules out.
  virtual double distance_bound(std::span<const double> a, std::span<const double> b) const {
    return sampling_distance(metric(), a.first(index_dimension()), b.first(index_dimension()));
  }
  virtual void interpolate(std::span<const double> a, std::span<const double> b, double t,
                           std::span<double> out) const {
    sampling_interpolate(metric(), a, b, t, out);
  }
  // Steering: the coordinates at most `step` along the motion a → b from a, into `out` — b itself
  // when distance(a, b) <= step or step is 0 (all the way), otherwise interpolate's point a
  // fraction step / distance of the way, on the very motion motion_is_free certifies. From
  // SteerFrom::end, `step` before b on that motion instead (a itself when nearer): a tree grown
  // toward its root. Returns distance(a, b). The planners' only steering (step_toward), and
  // Python's space.steer.
  double steer(std::span<const double> a, std::span<const double> b, double step, std::span<double> out,
               SteerFrom from = SteerFrom::start) const {
    const double d = distance(a, b);
    const auto target = from == SteerFrom::start ? b : a;
    if (step <= 0 || d <= step) std::copy(target.begin(), target.end(), out.begin());
    else interpolate(a, b, from == SteerFrom::start ? step / d : 1 - step / d, out);
    return d;
  }
  // Why coordinates lie where sample() never draws (beyond the sampling box), in words; nullopt
  // when they do not, and by default (the torus, where every finite angle is a joint's).
  virtual std::optional<std::string> outside(std::span<const double> /*coordinates*/) const { return std::nullopt; }
  // The largest distance between two configurations that sample() can give: default steps are
  // fractions of it.
  virtual double extent() const = 0;
  // The measure of the sampled region in the metric's units (area, the torus's (2π)^n): RRT*'s
  // rewiring radius.
  virtual double volume() const = 0;

  // A configuration drawn uniformly from the region (the reference point's box, the torus), as
  // coordinates; it may be in collision.
  virtual void sample(SamplingRandom&, std::span<double> coordinates) const = 0;
  virtual void coordinates(const Configuration&, std::span<double> out) const = 0;
  // The configuration at these coordinates (exactly: the doubles' own values).
  virtual Configuration configuration(std::span<const double> coordinates) const = 0;

  // Free (contact allowed where the space allows it), decided exactly.
  virtual bool is_free(const Configuration&) = 0;
  // The motion from → to (sampling_interpolate's) proved free for every configuration on it;
  // false when it collides or cannot be proved free.
  virtual bool motion_is_free(const Configuration& from, const Configuration& to) = 0;
  // Clearance reuse. A space that keeps free regions measures one with free_region(c), null
  // exactly when c is not free; motion_is_free_between(from, to, …) then certifies what the ends'
  // regions (each made by free_region for that very configuration, or null when not known) leave
  // uncovered, and decides as motion_is_free does. By default a space keeps none.
  virtual bool keeps_free_regions() const { return false; }
  virtual std::shared_ptr<const FreeRegion> free_region(const Configuration&) { return nullptr; }
  virtual bool motion_is_free_between(const Configuration& from, const Configuration& to,
                                      const FreeRegion* /*from_region*/, const FreeRegion* /*to_region*/) {
    return motion_is_free(from, to);
  }
  // Why a query cannot be planned (a start or goal that is not free, angles of the wrong count),
  // in one sentence naming what it hits; nullopt when it can.
  virtual std::optional<std::string> query_not_free(const Query&) = 0;
  // Why no motion joins the query's start and goal, when the space can prove it (a car whose
  // start and goal lie in different components of its reference point's free space); nullopt when
  // it cannot, and by default.
  virtual std::optional<std::string> no_path(const Query&) { return std::nullopt; }
  // Why the query has no configuration to end at although a path might exist (an arm's hand at a
  // point whose every inverse-kinematics solution found collides): the query is then not_found.
  // Asked after no_path; nullopt, and by default, when goals() has one.
  virtual std::optional<std::string> no_goal_found(const Query&) { return std::nullopt; }
  // The query's start and goal as the path gives them (an arm's angles normalised).
  virtual Configuration start(const Query&) const = 0;
  virtual Configuration goal(const Query&) const = 0;
  // The configurations a path may end at, in a fixed order: the query's goal alone by default; several
  // where the goal is a set (an arm's hand at a point: its collision-free IK solutions). Called once per
  // query, after query_not_free, no_path and no_goal_found have accepted the query; never empty then.
  virtual std::vector<Configuration> goals(const Query& query) { return {goal(query)}; }
  // The certificate's words for a path of certified motions.
  virtual std::string certificate_method() const = 0;
  // Why a path of certified motions is still not a valid motion as a whole, or nullopt (the
  // default): in a polygon world a path may touch a pinch point, where C-obstacles meet at a
  // point, but must leave it into the free wedge it arrived from — which no motion alone can tell
  // (a roadmap keeps earlier queries' ends as milestones, and one may sit on a pinch point).
  virtual std::optional<std::string> why_path_invalid(const std::vector<Configuration>&) { return std::nullopt; }
  // The path of certified motions as the report gives it, and the space's own facts about it (a
  // car's curves cut at their segments' joints, its gear changes). The path itself by default.
  virtual std::vector<Configuration> reported_path(std::vector<Configuration> path, Facts&) const { return path; }
};

// Makes the space of a problem (which outlives it): the sampling planners' registry entries are
// built with one, so one planner source serves every space.
template <class Space>
using SamplingSpaceFactory = std::function<std::unique_ptr<SamplingSpace<Space>>(const typename Space::Problem&)>;

}  // namespace polyplan
