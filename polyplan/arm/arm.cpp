#include <polyplan/arm/arm.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace polyplan {

void joint_positions_into(const Arm& arm, const JointAngles& angles, std::vector<Eigen::Vector2d>& out,
                          std::vector<double>* headings, std::vector<Eigen::Vector2d>* directions) {
  const std::size_t n = arm.links.size();
  if (angles.size() != n)
    throw std::invalid_argument("joint_positions: " + std::to_string(angles.size()) + " angles for an arm of " +
                                std::to_string(n) + " links");
  out.resize(n + 1);
  out[0] = Eigen::Vector2d::Zero();
  if (headings) headings->resize(n);
  if (directions) directions->resize(n);
  // Relative angles: link k points along the sum of the first k+1 angles.
  double heading = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(angles[k]))
      throw std::invalid_argument("joint_positions: angle " + std::to_string(k) + " is not finite");
    heading += angles[k];
    const Eigen::Vector2d direction(std::cos(heading), std::sin(heading));
    out[k + 1] = out[k] + arm.links[k] * direction;
    if (headings) (*headings)[k] = heading;
    if (directions) (*directions)[k] = direction;
  }
}

std::vector<Eigen::Vector2d> joint_positions(const Arm& arm, const JointAngles& angles) {
  std::vector<Eigen::Vector2d> out;
  joint_positions_into(arm, angles, out);
  return out;
}

std::size_t link_outline_into(const Arm& arm, const std::vector<Eigen::Vector2d>& joints, std::size_t link,
                              std::array<Eigen::Vector2d, 4>& corners) {
  if (link >= arm.links.size() || link + 1 >= joints.size())
    throw std::invalid_argument("link_outline: no link " + std::to_string(link) + " (the arm has " +
                                std::to_string(arm.links.size()) + " links, " + std::to_string(joints.size()) +
                                " joint positions given)");
  const Eigen::Vector2d& from = joints[link];
  const Eigen::Vector2d& to = joints[link + 1];
  if (arm.link_width == 0) {
    corners[0] = from;
    corners[1] = to;
    return 2;
  }
  // The left normal of the link scaled to half the width. Dividing by the nominal length rather
  // than |to − from| saves a square root; the two differ by rounding only.
  const Eigen::Vector2d along = to - from;
  const Eigen::Vector2d half = Eigen::Vector2d(-along.y(), along.x()) * (arm.link_width / 2 / arm.links[link]);
  corners[0] = from - half;
  corners[1] = to - half;
  corners[2] = to + half;
  corners[3] = from + half;
  return 4;
}

std::vector<Eigen::Vector2d> link_outline(const Arm& arm, const std::vector<Eigen::Vector2d>& joints,
                                          std::size_t link) {
  std::array<Eigen::Vector2d, 4> corners;
  const std::size_t n = link_outline_into(arm, joints, link, corners);
  return {corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(n)};
}

}  // namespace polyplan
