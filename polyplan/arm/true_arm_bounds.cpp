#include <polyplan/arm/detail/true_arm_bounds.hpp>

#include <polyplan/arm/detail/outward_rounding.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan::detail {
namespace {

// With RoundingUpward in force: the largest distance from p to a point of the box x × y, rounded up.
double radius_of(const Eigen::Vector2d& p, const Interval& x, const Interval& y) {
  const double dx = farthest_from(p.x(), x.inf(), x.sup()), dy = farthest_from(p.y(), y.inf(), y.sup());
  return std::sqrt(dx * dx + dy * dy);
}

Interval interval(const std::array<double, 2>& range) { return Interval(range[0], range[1]); }

}  // namespace

void TrueArmBounds::enclose(const JointAngles& q, std::span<const double> spread, const std::vector<double>& headings,
                            const std::vector<Eigen::Vector2d>& directions,
                            const std::vector<Eigen::Vector2d>& joints) {
  const std::size_t n = arm_->joints();
  x_.resize(n + 1);
  y_.resize(n + 1);
  radius_.resize(n + 1);
  normal_x_.resize(n);
  normal_y_.resize(n);
  x_[0] = y_[0] = {0.0, 0.0};  // the base is the origin, exactly
  radius_[0] = 0;
  const Interval half_width = Interval(arm_->link_width) / 2;
  Interval heading(0), x(0), y(0);
  for (std::size_t k = 0; k < n; ++k) {
    const double s = spread.empty() ? 0.0 : spread[k];
    heading += Interval(q[k]) + Interval(-s, s);
    // cos and sin are 1-Lipschitz: over the heading's range they stay within `off` of the
    // computed values at the computed heading.
    const double off = farthest_from(headings[k], heading.inf(), heading.sup()) + trig_error;
    const Interval c = Interval(directions[k].x()) + Interval(-off, off);
    const Interval sn = Interval(directions[k].y()) + Interval(-off, off);
    x += Interval(arm_->links[k]) * c;
    y += Interval(arm_->links[k]) * sn;
    x_[k + 1] = {x.inf(), x.sup()};
    y_[k + 1] = {y.inf(), y.sup()};
    radius_[k + 1] = radius_of(joints[k + 1], x, y);
    const Interval nx = -(half_width * sn), ny = half_width * c;
    normal_x_[k] = {nx.inf(), nx.sup()};
    normal_y_[k] = {ny.inf(), ny.sup()};
  }
}

double TrueArmBounds::link_radius(std::size_t k, std::span<const Eigen::Vector2d> corners) const {
  if (corners.size() == 2) {
    const double ends = std::max(radius_[k], radius_[k + 1]);
    return arm_->link_width > 0 ? ends + arm_->link_width / 2 : ends;
  }
  // link_outline_into's order: joint k − normal, joint k+1 − normal, joint k+1 + normal, joint k + normal.
  const Interval nx = interval(normal_x_[k]), ny = interval(normal_y_[k]);
  const std::size_t joint_of[4] = {k, k + 1, k + 1, k};
  double largest = 0;
  for (int i = 0; i < 4; ++i) {
    const Interval x = interval(x_[joint_of[i]]), y = interval(y_[joint_of[i]]);
    const bool minus = i < 2;
    largest = std::max(
        largest, radius_of(corners[static_cast<std::size_t>(i)], minus ? x - nx : x + nx, minus ? y - ny : y + ny));
  }
  return largest;
}

}  // namespace polyplan::detail
