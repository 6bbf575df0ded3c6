#include <polyplan/arm/arm_sampling_space.hpp>

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_goal_set.hpp>
#include <polyplan/arm/arm_motion.hpp>

#include <numbers>
#include <optional>

namespace polyplan {
namespace {

// A configuration's clearances (arm_motion.hpp, measure_end_clearances): what a tree node or a
// milestone proves about the motions that leave it or reach it.
struct ArmFreeRegion final : FreeRegion {
  ArmClearances clearances;
};

const ArmClearances* clearances_of(const FreeRegion* region) {
  return region ? &static_cast<const ArmFreeRegion*>(region)->clearances : nullptr;  // this space made it
}

class ArmSamplingSpace final : public SamplingSpace<PlanarArm> {
 public:
  explicit ArmSamplingSpace(const ArmProblem& problem) : checker_(problem) {}

  std::size_t dimension() const override { return checker_.arm().joints(); }
  SamplingMetric metric() const override { return SamplingMetric::torus; }
  double extent() const override { return static_cast<double>(dimension()) * std::numbers::pi; }
  double volume() const override { return std::pow(two_pi, static_cast<double>(dimension())); }

  void sample(SamplingRandom& random, std::span<double> out) const override {
    for (double& angle : out) angle = normalize_angle(uniform01(random) * two_pi);
  }
  void coordinates(const JointAngles& q, std::span<double> out) const override {
    for (std::size_t i = 0; i < q.size(); ++i)
      out[i] = normalize_angle(q[i]);  // the configurations' own angles are normalised
  }
  JointAngles configuration(std::span<const double> c) const override { return JointAngles(c.begin(), c.end()); }

  bool is_free(const JointAngles& q) override { return checker_.is_free(q); }
  bool motion_is_free(const JointAngles& from, const JointAngles& to) override {
    return polyplan::motion_is_free(checker_, from, to);
  }
  bool keeps_free_regions() const override { return true; }
  std::shared_ptr<const FreeRegion> free_region(const JointAngles& q) override {
    auto region = std::make_shared<ArmFreeRegion>();
    measure_end_clearances(checker_, q, region->clearances);
    if (region->clearances.contact) return nullptr;
    return region;
  }
  bool motion_is_free_between(const JointAngles& from, const JointAngles& to, const FreeRegion* from_region,
                              const FreeRegion* to_region) override {
    return certify_motion(checker_, from, to, clearances_of(from_region), clearances_of(to_region)).free();
  }
  std::optional<std::string> query_not_free(const ArmQuery& query) override {
    return polyplan::query_not_free(checker_, query);
  }
  std::optional<std::string> no_path(const ArmQuery& query) override { return why_none(query, PlanStatus::no_path); }
  std::optional<std::string> no_goal_found(const ArmQuery& query) override {
    return why_none(query, PlanStatus::not_found);
  }
  JointAngles start(const ArmQuery& query) const override { return normalize_angles(query.start); }
  // A goal in the workspace has no one configuration: goals() gives its set.
  JointAngles goal(const ArmQuery& query) const override { return normalize_angles(query.goal); }
  std::vector<JointAngles> goals(const ArmQuery& query) override { return goal_set(query).configurations(); }
  std::string certificate_method() const override { return "conservative advancement (arm/arm_motion.hpp)"; }
  std::vector<JointAngles> reported_path(std::vector<JointAngles> path, Facts& facts) const override {
    if (goal_set_ && !path.empty()) set_goal_facts(goal_set_->set, goal_set_->set.index_of(path.back()), facts);
    return path;
  }

 private:
  // The last query's goal set, made once for the questions plan() asks of one query in turn.
  struct GoalSetOf {
    ArmQuery query;
    ArmGoalSet set;
  };
  const ArmGoalSet& goal_set(const ArmQuery& query) {
    if (!goal_set_ || goal_set_->query.goal != query.goal || goal_set_->query.goal_point != query.goal_point)
      goal_set_ = GoalSetOf{query, arm_goal_set(checker_, query)};
    return goal_set_->set;
  }
  std::optional<std::string> why_none(const ArmQuery& query, PlanStatus status) {
    const ArmGoalSet& set = goal_set(query);
    if (set.goals.empty() && set.status == status) return set.why_none;
    return std::nullopt;
  }

  ArmCollisionChecker checker_;
  std::optional<GoalSetOf> goal_set_;
};

}  // namespace

std::unique_ptr<SamplingSpace<PlanarArm>> arm_sampling_space(const ArmProblem& problem) {
  return std::make_unique<ArmSamplingSpace>(problem);
}

}  // namespace polyplan
