#pragma once
// What an arm file describes (docs/design.md "Arm file"): a planar n-link arm with its base at the
// origin, the obstacles and obstacle points around it, and the queries — the arm's counterpart of
// World. Plain data; kinematics and collision are in arm/, the reader in io/arm_reader.hpp.
#include <polyplan/geometry/world.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {

// Radians, relative joint angles (θ1 absolute from +x, θi relative to link i−1).
using JointAngles = std::vector<double>;

struct Arm {
  std::vector<double> links;  // lengths > 0; base at the origin
  // The lengths as the file wrote them, exactly (a decimal 0.1 is 1/10), one per link; empty for an
  // arm built in code (the doubles' values are then exact). They decide, exactly, whether a point
  // lies on the boundary of the annulus the hand reaches (inverse_kinematics.hpp's hand_reach).
  std::vector<Rational> exact_links{};
  // 0: links are segments; w > 0: each link is the w-wide rectangle on its segment (no end caps:
  // the rectangle ends at the joints).
  double link_width = 0;
  // false: links at different heights never collide with each other (the course's arm and car planning report). true:
  // two links that share no joint collide when they meet; adjacent links never do.
  bool self_collision = false;
  // Per joint [lo, hi], radians, lo <= hi: the angles a joint may take, read round the circle (an
  // angle a is within them when a + 2πk lies in [lo, hi] for some whole k). Empty: no limits. Inverse
  // kinematics keeps to them (a workspace goal's configurations); the planners' paths do not.
  std::vector<std::pair<double, double>> limits{};

  std::size_t joints() const { return links.size(); }
  // The sum of the links plus w/2: every point of the arm, in every configuration, lies within
  // this distance of the base.
  double reach() const {
    double sum = 0;
    for (double l : links) sum += l;
    return sum + link_width / 2;
  }
};

// A goal in the workspace rather than in joint angles: the end effector (the end of the last link)
// at `point`, and where `orientation` is given the last link's absolute angle θ1 + … + θn there
// (radians). The query then ends at any of the configurations that put it there.
struct WorkspaceGoal {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  std::optional<double> orientation;
  // The point as the file wrote it, exactly, when it was read from one (see Arm::exact_links).
  std::optional<ExactPoint> exact_point{};

  friend bool operator==(const WorkspaceGoal& a, const WorkspaceGoal& b) {
    return a.point.x() == b.point.x() && a.point.y() == b.point.y() && a.orientation == b.orientation &&
           a.exact_point == b.exact_point;
  }
};

struct ArmQuery {
  std::string name;  // "start/goal" (the top-level pair), the query's "name", or "queries[2]"
  JointAngles start;
  JointAngles goal;  // empty when the goal is in the workspace (goal_point)
  std::optional<WorkspaceGoal> goal_point = std::nullopt;
};

struct ArmProblem {
  std::string source;  // the file read, for messages
  Arm arm;
  std::vector<PolygonWithHoles> obstacles;  // exact, validated and oriented as in World
  std::vector<std::string> obstacle_names;  // "obstacles[3]"
  std::vector<Eigen::Vector2d> points;      // point obstacles
  // The top-level start/goal first (if present), then `queries` in file order. Names are unique.
  std::vector<ArmQuery> queries;
};

}  // namespace polyplan
