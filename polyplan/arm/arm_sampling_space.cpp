#include <polyplan/arm/arm_sampling_space.hpp>

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>

#include <numbers>

namespace polyplan {
namespace {

JointAngles normalized(JointAngles q) {
  for (double& angle : q) angle = normalize_angle(angle);
  return q;
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
    for (std::size_t i = 0; i < q.size(); ++i) out[i] = normalize_angle(q[i]);  // the configurations' own angles are normalised
  }
  JointAngles configuration(std::span<const double> c) const override { return JointAngles(c.begin(), c.end()); }

  bool is_free(const JointAngles& q) override { return checker_.is_free(q); }
  bool motion_is_free(const JointAngles& from, const JointAngles& to) override { return polyplan::motion_is_free(checker_, from, to); }
  std::optional<std::string> query_not_free(const ArmQuery& query) override { return polyplan::query_not_free(checker_, query); }
  JointAngles start(const ArmQuery& query) const override { return normalized(query.start); }
  JointAngles goal(const ArmQuery& query) const override { return normalized(query.goal); }
  std::string certificate_method() const override { return "conservative advancement (arm/arm_motion.hpp)"; }

 private:
  ArmCollisionChecker checker_;
};

}  // namespace

std::unique_ptr<SamplingSpace<PlanarArm>> arm_sampling_space(const ArmProblem& problem) {
  return std::make_unique<ArmSamplingSpace>(problem);
}

}  // namespace polyplan
