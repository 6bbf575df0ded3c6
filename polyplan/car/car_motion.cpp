#include <polyplan/car/car_motion.hpp>

#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/rotation.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan {

SteeringPath shortest_car_path(const CarSteering& steering, const CarPose& from, const CarPose& to) {
  return steering.reverse ? shortest_reeds_shepp_path(from, to, steering.turning_radius)
                          : shortest_dubins_path(from, to, steering.turning_radius);
}

double car_distance(const CarSteering& steering, const CarPose& from, const CarPose& to) {
  return steering.reverse ? reeds_shepp_distance(from, to, steering.turning_radius)
                          : dubins_distance(from, to, steering.turning_radius);
}

std::vector<CarState> states_along(const CarPose& from, const SteeringPath& path, const CarPose& to, double radius) {
  std::vector<CarState> states;
  CarPose at = from;
  for (const SteeringSegment& segment : path.segments) {
    at = drive(at, segment, radius, segment.length);
    states.push_back({at, segment});
  }
  if (!states.empty()) {  // the curve's end is `to` to its rounding (arrives()); the heading as the car turned
    CarPose& end = states.back().pose;
    end = {to.x, to.y, end.theta + std::remainder(to.theta - end.theta, 2 * pi)};
  }
  return states;
}

// Each segment starts where the one before ends, at the states' own poses (only the last, which
// starts nothing, is moved onto `to`): certifying from them certifies the states returned.
std::optional<std::vector<CarState>> certified_states(const CarCollision& car, const CarPose& from,
                                                      const SteeringPath& path, const CarPose& to) {
  std::vector<CarState> states = states_along(from, path, to, car.turning_radius());
  for (std::size_t i = 0; i < states.size(); ++i) {
    const CarPose& start = i == 0 ? from : states[i - 1].pose;
    if (!car.segment_is_free(start, states[i].arrival)) return std::nullopt;
    // The last state was moved from the curve's computed end onto `to`: that step must stay within
    // what the last segment's certificate encloses.
    if (i + 1 == states.size() &&
        !car.arrival_is_covered(start, states[i].arrival,
                                drive(start, states[i].arrival, car.turning_radius(), states[i].arrival.length), to))
      return std::nullopt;
  }
  return states;
}

std::size_t gear_changes(const std::vector<CarState>& path) {
  std::size_t changes = 0;
  int gear = 0;
  for (const CarState& s : path) {
    if (s.arrival.length == 0) continue;
    if (gear != 0 && s.arrival.gear != gear) ++changes;
    gear = s.arrival.gear;
  }
  return changes;
}

bool arrives(const CarPose& end, const CarPose& at, double radius) {
  const double scale = 1e-9 * std::max({std::abs(at.x), std::abs(at.y), radius});  // the world's own scale
  return std::hypot(end.x - at.x, end.y - at.y) <= scale &&
         radius * std::abs(std::remainder(end.theta - at.theta, 2 * pi)) <= scale;
}

}  // namespace polyplan
