#include <polyplan/car/car_sampling_space.hpp>

#include <polyplan/car/car_facts.hpp>
#include <polyplan/car/car_motion.hpp>
#include <polyplan/car/car_query.hpp>
#include <polyplan/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polyplan {
namespace {

CarPose pose_at(std::span<const double> c) { return {c[0], c[1], c[2]}; }

class CarSamplingSpace final : public SamplingSpace<SteeredCar> {
 public:
  explicit CarSamplingSpace(const World& world)
      : steering_(world.robot.car.value_or(CarSteering{})), collision_(world), box_(car_sampling_box(world)) {
    if (collision_.body_holds_reference_point()) holonomic_.emplace(world);
  }

  std::size_t dimension() const override { return 3; }
  SamplingMetric metric() const override { return SamplingMetric::euclidean; }
  std::size_t index_dimension() const override { return 2; }
  bool distance_is_metric() const override { return false; }
  // Even Reeds–Shepp's, whose lengths agree both ways: between curves of one length the way
  // back may choose another, so each way is certified on its own.
  bool symmetric() const override { return false; }
  double distance(std::span<const double> a, std::span<const double> b) const override {
    return car_distance(steering_, pose_at(a), pose_at(b));
  }
  // The heading turns by at most length / radius: a curve is at least as long as its ends lie
  // apart, and at least the radius times the heading change (the short way round).
  double distance_bound(std::span<const double> a, std::span<const double> b) const override {
    return std::max(std::hypot(b[0] - a[0], b[1] - a[1]),
                    steering_.turning_radius * std::abs(std::remainder(b[2] - a[2], two_pi)));
  }
  void interpolate(std::span<const double> a, std::span<const double> b, double t,
                   std::span<double> out) const override {
    const CarPose from = pose_at(a);
    const SteeringPath path = shortest_car_path(steering_, from, pose_at(b));
    const CarPose at = pose_along(path, from, steering_.turning_radius, t * path.length());
    out[0] = at.x, out[1] = at.y, out[2] = at.theta;
  }
  // The box's diagonal and a full turn: about the longest curve between two drawn poses.
  double extent() const override {
    return std::hypot(box_.xmax - box_.xmin, box_.ymax - box_.ymin) + 2 * std::numbers::pi * steering_.turning_radius;
  }
  // Headings measured in lengths (radians times the radius), as the curves' lengths count them.
  double volume() const override {
    return (box_.xmax - box_.xmin) * (box_.ymax - box_.ymin) * 2 * std::numbers::pi * steering_.turning_radius;
  }

  void sample(SamplingRandom& random, std::span<double> out) const override {
    out[0] = box_.xmin + uniform01(random) * (box_.xmax - box_.xmin);
    out[1] = box_.ymin + uniform01(random) * (box_.ymax - box_.ymin);
    out[2] = uniform01(random) * two_pi;
  }
  // The heading may be any angle: only the position has bounds.
  std::optional<std::string> outside(std::span<const double> c) const override {
    return outside_box(c[0], c[1], box_.xmin, box_.ymin, box_.xmax, box_.ymax);
  }
  void coordinates(const CarState& state, std::span<double> out) const override {
    out[0] = state.pose.x, out[1] = state.pose.y, out[2] = state.pose.theta;
  }
  CarState configuration(std::span<const double> c) const override { return {pose_at(c), {}}; }

  bool is_free(const CarState& state) override { return collision_.pose_is_free(state.pose); }
  bool motion_is_free(const CarState& from, const CarState& to) override {
    return states_between(from, to).has_value();
  }
  std::optional<std::string> query_not_free(const Query& query) override {
    return car_query_not_free(collision_, query);
  }
  std::optional<std::string> no_path(const Query& query) override {
    return car_query_unreachable(holonomic_ ? &*holonomic_ : nullptr, query);
  }
  CarState start(const Query& query) const override { return {start_pose(query), {}}; }
  CarState goal(const Query& query) const override { return {goal_pose(query), {}}; }
  std::string certificate_method() const override { return CarCollision::method; }

  // Each motion cut at its segments' joints (certified already: the planner certified every motion
  // of the path once more before it asks); each joint of the sampled path kept as it was certified
  // from (its heading as drawn, not as the car turned to it).
  std::vector<CarState> reported_path(std::vector<CarState> path, Facts& facts) const override {
    std::vector<CarState> cut{path.front()};
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const CarPose &from = path[i].pose, &to = path[i + 1].pose;
      std::vector<CarState> states =
          states_along(from, shortest_car_path(steering_, from, to), to, steering_.turning_radius);
      if (!states.empty()) states.back().pose = to;
      cut.insert(cut.end(), states.begin(), states.end());
    }
    facts.set(CarFacts::gear_changes, gear_changes(cut));
    return cut;
  }

 private:
  std::optional<std::vector<CarState>> states_between(const CarState& from, const CarState& to) const {
    return certified_states(collision_, from.pose, shortest_car_path(steering_, from.pose, to.pose), to.pose);
  }

  CarSteering steering_;
  CarCollision collision_;
  CarSamplingBox box_;
  std::optional<HolonomicDistance> holonomic_;
};

}  // namespace

std::unique_ptr<SamplingSpace<SteeredCar>> car_sampling_space(const World& world) {
  return std::make_unique<CarSamplingSpace>(world);
}

}  // namespace polyplan
