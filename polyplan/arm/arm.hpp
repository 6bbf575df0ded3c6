#pragma once
// A planar n-link arm and its forward kinematics (Eigen). The base is at the origin; θ1 is the
// absolute angle of link 1 (from +x, counter-clockwise), θi the angle of link i relative to
// link i−1. In prose links are numbered from 1 (link 1 touches the base); in code, indices into
// `links`, joint_positions and link_outline start at 0, so link k runs from joints[k] to joints[k+1].
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace polyplan {

// joints()+1 points: [0] = base (0, 0), [k+1] = the end of links[k]. Throws std::invalid_argument
// when the angle count differs from the link count or an angle is not finite.
std::vector<Eigen::Vector2d> joint_positions(const Arm&, const JointAngles&);
// The same into `out` (resized; no allocation once it has the size), for hot loops. When given,
// `headings` and `directions` receive, for each link k, the heading as computed (the sum of the
// first k+1 angles, in doubles) and its direction (cos, sin of that heading, as libm computes
// them): what arm/detail/true_arm_bounds.hpp encloses the true arm with.
void joint_positions_into(const Arm&, const JointAngles&, std::vector<Eigen::Vector2d>& out,
                          std::vector<double>* headings = nullptr, std::vector<Eigen::Vector2d>* directions = nullptr);

// The outline of links[link] for the given joint positions: its 2 end points (a segment, width 0)
// or the 4 corners of its rectangle, counter-clockwise, starting at the corner to the right of
// joints[link]. Throws std::invalid_argument for a link index out of range or too few joints.
std::vector<Eigen::Vector2d> link_outline(const Arm&, const std::vector<Eigen::Vector2d>& joints, std::size_t link);
// The same into a fixed array; returns how many corners are used (2 or 4). For hot loops.
std::size_t link_outline_into(const Arm&, const std::vector<Eigen::Vector2d>& joints, std::size_t link,
                              std::array<Eigen::Vector2d, 4>& corners);

}  // namespace polyplan
