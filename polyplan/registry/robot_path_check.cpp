#include <polyplan/registry/robot_path_check.hpp>

#include <polyplan/geometry/round_world_check.hpp>

#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>
#if POLYPLAN_WITH_CAR
#include <polyplan/car/car_path_check.hpp>
#include <polyplan/io/car_path_reader.hpp>
#endif
#if POLYPLAN_WITH_ROTATION
#include <polyplan/rotation/pose_path_check.hpp>
#endif
#if POLYPLAN_WITH_ARM
#include <polyplan/arm/arm_path_check.hpp>
#endif

namespace polyplan {
namespace {

// Used only where a family is left out of the build.
[[noreturn, maybe_unused]] void without(const std::string& source, const std::string& family, const std::string& what) {
  throw InputError(source + ": " + what + " is checked by the " + family +
                   " planners' library, which this polyplan is built without (cmake -DPOLYPLAN_FAMILIES=" + family +
                   " or all)");
}

PathCheck check_arm_rows(const ArmProblem& arm, const std::vector<std::vector<Rational>>& rows) {
#if POLYPLAN_WITH_ARM
  std::vector<JointAngles> path;
  for (const auto& row : rows) {
    path.emplace_back();
    for (const Rational& angle : row) path.back().push_back(to_double(angle));
  }
  return check_arm_path(arm, path);
#else
  without(arm.source, "arm", "an arm's path");
#endif
}

PathCheck check_pose_rows(const World& world, const std::vector<std::vector<Rational>>& rows) {
#if POLYPLAN_WITH_ROTATION
  std::vector<Pose> poses;
  for (std::size_t i = 0; i < rows.size(); ++i)
    poses.push_back(pose_from_row(rows[i], "path[" + std::to_string(i) + "]"));
  return check_pose_path(world, poses);
#else
  without(world.source, "rotation", "a rotating robot's path");
#endif
}

}  // namespace

PathCheck check_path_file(const Problem& problem, const std::string& path_file) {
  if (const ArmProblem* arm = problem.arm()) return check_arm_rows(*arm, read_path_rows(path_file));
  const World& world = *problem.world();
  if (world.robot.car) {
#if POLYPLAN_WITH_CAR
    return check_car_path(world, read_car_path(path_file));
#else
    without(world.source, "car", "a car's path");
#endif
  }
  const auto rows = read_path_rows(path_file);
  if (rows.front().size() == 3 || rows.front().size() == 4) return check_pose_rows(world, rows);
  if (rows.front().size() != 2)
    throw InputError(path_file + ": path[0]: " + std::to_string(rows.front().size()) +
                     " numbers: expected [x, y] points, or [x, y, degrees] or [x, y, sin, cos] poses");
  std::vector<ExactPoint> points;
  for (const auto& row : rows) points.push_back({row[0], row[1]});
  return check_translating_path(problem, points);
}

PathCheck check_translating_path(const Problem& problem, const std::vector<ExactPoint>& points) {
  const World& world = *problem.world();
  if (round_features(world).empty()) return check_path(problem.cspace(), points);
  return problem.round_world().check_path(points);  // the problem's, built once
}

}  // namespace polyplan
