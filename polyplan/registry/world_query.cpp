#include <polyplan/registry/detail/world_door.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <cmath>

namespace polyplan::detail {
namespace {

// θ as the world reader bounds it: a finite number of degrees within ±1e6.
double degrees(const Rational& theta, const std::string& what) {
  const double value = to_double(theta);
  if (!(std::abs(value) <= 1e6))
    throw InputError(what + ": theta " + to_string(theta) + " degrees: expected an angle within ±1e6 degrees");
  return value;
}

void read_pose(const std::vector<Rational>& numbers, const std::string& what, ExactPoint& at,
               std::optional<double>& theta) {
  if (numbers.size() != 2 && numbers.size() != 3)
    throw InputError(what + ": expected (x, y) or (x, y, theta), got " + std::to_string(numbers.size()) + " number(s)");
  at = {numbers[0], numbers[1]};
  if (numbers.size() == 3) theta = degrees(numbers[2], what + "[2] (theta, degrees)");
}

}  // namespace

Query world_query(const QuerySpec& spec) {
  if (!spec.goal_point.empty() || spec.goal_orientation)
    throw InputError("goal_point and goal_orientation are an arm's (its hand at a point), not a World's");
  Query q;
  q.name = spec.name;
  read_pose(spec.start, "start", q.start, q.start_theta);
  read_pose(spec.goal, "goal", q.goal, q.goal_theta);
  return q;
}

}  // namespace polyplan::detail
