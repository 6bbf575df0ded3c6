#include <polyplan/rotation/rotation_layers.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/turn_enclosure.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace polyplan {

OrientationSet::OrientationSet(const OrientationOptions& o) {
  const double to = o.to.value_or(o.from + 360);
  std::string range = "[";  // appended: GCC 12 takes "[" + string for an out-of-bounds copy
  range += angle_text(o.from);
  range += ", ";
  range += angle_text(to);
  range += ']';
  if (!std::isfinite(o.from) || !std::isfinite(to) || to < o.from)
    throw std::invalid_argument("rotation-from/rotation-to: the range " + range + " is reversed or not finite");
  const double width = to - o.from;
  if (width > 360) throw std::invalid_argument("rotation-from/rotation-to: the range " + range + " is wider than 360°");
  whole_circle_ = width == 360;
  std::size_t intervals = 0;  // steps from `from` to `to`
  if (o.count > 0) {
    if (o.count > max_rotation_layers)
      throw std::invalid_argument("rotation-count " + std::to_string(o.count) + ": more than " +
                                  std::to_string(max_rotation_layers) + " layers");
    if (width == 0 && o.count != 1)
      throw std::invalid_argument("rotation-count: an empty range " + range + " has one layer");
    if (!whole_circle_ && width > 0 && o.count < 2)
      throw std::invalid_argument("rotation-count: the range " + range + " needs at least two layers, its ends");
    intervals = whole_circle_ ? o.count : o.count - 1;
    step_ = intervals == 0 ? 360 : width / static_cast<double>(intervals);
  } else {
    if (!std::isfinite(o.step) || o.step <= 0)
      throw std::invalid_argument("rotation-step " + detail::show_number(o.step) +
                                  ": expected a number of degrees > 0");
    const double steps = width / o.step;
    if (steps > static_cast<double>(max_rotation_layers))
      throw std::invalid_argument("rotation-step " + angle_text(o.step) + ": more than " +
                                  std::to_string(max_rotation_layers) + " layers over " + range);
    intervals = static_cast<std::size_t>(std::llround(steps));
    // The step must divide the range: reading "0.1" gives a double, so "divides" is decided to
    // within rounding of the user's numbers (this picks the layers; it decides no collision).
    if (std::abs(static_cast<double>(intervals) * o.step - width) > 1e-9 * std::max(1.0, width))
      throw std::invalid_argument("rotation-step " + angle_text(o.step) + " does not divide the range " + range + " (" +
                                  detail::show_number(steps) + " steps)");
    step_ = o.step;
    if (whole_circle_ && intervals == 0) intervals = 1;
  }
  const std::size_t n = whole_circle_ ? intervals : intervals + 1;
  if (n > 1 && step_ >= 180)
    throw std::invalid_argument(
        "rotation-step " + angle_text(step_) +
        ": neighbouring layers must be less than 180° apart (a turn is enclosed the short way)");
  for (std::size_t k = 0; k < n; ++k)
    degrees_.push_back(k + 1 == n && !whole_circle_ && n > 1 ? to : o.from + static_cast<double>(k) * step_);
}

std::vector<std::pair<std::size_t, std::size_t>> OrientationSet::turns() const {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const std::size_t n = size();
  for (std::size_t k = 0; k + 1 < n; ++k) out.emplace_back(k, k + 1);
  if (whole_circle_ && n >= 3) out.emplace_back(n - 1, 0);
  return out;
}

std::optional<double> OrientationSet::normalized(double degrees) const {
  const double from = degrees_.front();
  double a = std::fmod(degrees - from, 360.0);
  if (a < 0) a += 360.0;
  a += from;
  if (whole_circle_) return a;
  const double to = degrees_.back();
  if (a <= to) return a;
  if (a - 360 >= from) return a - 360;  // cannot happen for from <= a < from + 360
  return std::nullopt;
}

std::optional<std::size_t> OrientationSet::layer_at(double degrees) const {
  const auto a = normalized(degrees);
  if (!a) return std::nullopt;
  for (std::size_t k = 0; k < size(); ++k)
    if (degrees_[k] == *a) return k;
  return std::nullopt;
}

std::vector<std::size_t> OrientationSet::nearest(double a) const {
  std::vector<std::size_t> best;
  double closest = 1e300;
  for (std::size_t k = 0; k < size(); ++k) {
    const double d = distance(degrees_[k], a);
    if (d < closest) {
      closest = d;
      best = {k};
    } else if (d == closest) {
      best.push_back(k);
    }
  }
  return best;
}

double OrientationSet::distance(double a, double b) const {
  const double d = std::abs(a - b);
  return whole_circle_ ? std::min(std::fmod(d, 360.0), 360.0 - std::fmod(d, 360.0)) : d;
}

World world_with_robot(const World& world, Robot robot) {
  World turned = world;
  turned.robot = std::move(robot);
  return turned;
}

void require_free_poses(const World& world) {
  std::map<double, std::unique_ptr<CSpace>> at_angle;
  for (const Query& q : world.queries)
    for (const auto& [what, point, theta] : {std::tuple{"start", &q.start, q.start_theta.value_or(0)},
                                             std::tuple{"goal", &q.goal, q.goal_theta.value_or(0)}}) {
      auto& cspace = at_angle[theta];
      if (!cspace)
        cspace = std::make_unique<CSpace>(world_with_robot(world, rotated(world.robot, exact_rotation(theta))));
      if (auto why = cspace->collision_at(*point))
        throw InputError(world.source + ": " + (q.name == "start/goal" ? std::string(what) : q.name + "." + what) +
                         " " + to_string(Pose{*point, {}, theta}) + ": not free: " + *why);
    }
}

RotationLayers::RotationLayers(const World& world, const OrientationSet& orientations)
    : world_(world), orientations_(orientations) {
  for (std::size_t k = 0; k < orientations_.size(); ++k) {
    RotationLayer layer;
    layer.degrees = orientations_.degrees(k);
    layer.rotation = exact_rotation(layer.degrees);
    layer.world = world_with_robot(world_, rotated(world_.robot, layer.rotation));
    layer.cspace = std::make_unique<CSpace>(layer.world);
    layers_.push_back(std::move(layer));
  }
  for (const auto& [from, to] : orientations_.turns()) {
    TurnLayer turn;
    turn.from = from;
    turn.to = to;
    turn.turn_degrees = polyplan::turn_degrees(layers_[from].rotation, layers_[to].rotation);
    turn.world = world_with_robot(world_, turn_enclosure(world_.robot, layers_[from].rotation, layers_[to].rotation));
    turn.cspace = std::make_unique<CSpace>(turn.world);
    // Each corner once, though a pinch vertex is on two rings.
    std::set<std::pair<Rational, Rational>> seen;
    const auto add_corners = [&](const Ring& ring) {
      for (const ExactPoint& p : ring)
        if (seen.emplace(p.x, p.y).second) turn.corners.push_back(p);
    };
    for (const FreeComponent& component : turn.cspace->free_components()) {
      add_corners(component.outer);
      for (const Ring& hole : component.holes) add_corners(hole);
    }
    turns_.push_back(std::move(turn));
  }
}

}  // namespace polyplan
