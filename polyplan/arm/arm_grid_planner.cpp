#include <polyplan/arm/arm_grid_planner.hpp>

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/grid_graph.hpp>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace polyplan {

namespace {

constexpr double degree = two_pi / 360;

// The grid's angles: cell k of a joint is k * step, k in [0, n).
struct AngleGrid {
  std::int64_t n;
  double step;
  bool torus;

  double angle(GridCoordinate k) const { return static_cast<double>(k) * step; }

  JointAngles configuration(const GridGraph& g, GridCell c) const {
    JointAngles q(g.dimensions());
    std::array<GridCoordinate, GridGraph::max_dimensions> at;
    g.coordinates(c, at);
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = angle(at[i]);
    return q;
  }

  // The two cells around angle a on one joint (equal when a is on a cell), nearest first.
  std::array<GridCoordinate, 2> around(double a) const {
    const double x = normalize_angle(a) / step;  // in [0, n)
    auto below = static_cast<std::int64_t>(std::floor(x));
    std::int64_t above = below + 1;
    if (above == n) above = torus ? 0 : n - 1;  // on the interval, [0, 2π) ends at cell n - 1
    if (below >= n) below = n - 1;              // x rounded up to n
    const bool below_nearer = x - std::floor(x) <= 0.5 || above == below;
    return below_nearer ? std::array{GridCoordinate(below), GridCoordinate(above)}
                        : std::array{GridCoordinate(above), GridCoordinate(below)};
  }
};

// Where the start (or goal) joins the grid: the first of the cells around it, nearest first (by the
// sum of the joints' distances), that is free and reached by a free motion.
struct Join {
  bool found = false;
  GridCell cell = 0;
};

Join join_to_grid(const GridGraph& g, const AngleGrid& grid, const ArmCollisionChecker& checker, const JointAngles& q,
                  double check_radians, std::size_t& motions) {
  const std::size_t joints = q.size();
  std::vector<std::array<GridCoordinate, 2>> options(joints);
  for (std::size_t i = 0; i < joints; ++i) options[i] = grid.around(q[i]);
  std::vector<std::pair<double, GridCell>> candidates;
  std::vector<GridCoordinate> at(joints);
  for (std::uint32_t mask = 0; mask < (1u << joints); ++mask) {
    double distance = 0;
    for (std::size_t i = 0; i < joints; ++i) {
      at[i] = options[i][(mask >> i) & 1u];
      distance += grid.torus ? angular_distance(q[i], grid.angle(at[i])) : std::fabs(normalize_angle(q[i]) - grid.angle(at[i]));
    }
    candidates.emplace_back(distance, g.cell(at));
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const auto& [distance, cell] : candidates) {
    if (!g.is_free(cell)) continue;
    ++motions;
    if (motion_is_free(checker, q, grid.configuration(g, cell), check_radians)) return {true, cell};
  }
  return {};
}

JointAngles normalized(const JointAngles& q) {
  JointAngles out(q.size());
  std::transform(q.begin(), q.end(), out.begin(), [](double a) { return normalize_angle(a); });
  return out;
}

}  // namespace

double arm_path_length(const std::vector<JointAngles>& path, bool torus) {
  double length = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    for (std::size_t i = 0; i < path[k].size(); ++i)
      length += torus ? angular_distance(path[k][i], path[k + 1][i])
                      : std::fabs(normalize_angle(path[k + 1][i]) - normalize_angle(path[k][i]));
  return length;
}

ArmGridPlan plan_arm_on_grid(const ArmProblem& problem, const ArmQuery& query, const ArmGridOptions& options) {
  const auto began = std::chrono::steady_clock::now();
  const std::size_t joints = problem.arm.joints();
  if (query.start.size() != joints || query.goal.size() != joints)
    throw std::invalid_argument("query " + query.name + ": " + std::to_string(joints) + " joint angles expected");
  const double cells_real = 360.0 / options.resolution_degrees;
  const auto n = static_cast<std::int64_t>(std::llround(cells_real));
  if (!(options.resolution_degrees > 0) || n < 3 || std::fabs(cells_real - static_cast<double>(n)) > 1e-9 * cells_real)
    throw std::invalid_argument("the grid resolution " + std::to_string(options.resolution_degrees) +
                                " degrees must divide 360 into at least 3 cells");
  const double check_degrees = options.check_degrees > 0 ? options.check_degrees : std::min(1.0, options.resolution_degrees);
  if (check_degrees > options.resolution_degrees * (1 + 1e-12))
    throw std::invalid_argument("checking motions every " + std::to_string(check_degrees) +
                                " degrees would skip configurations between grid cells " +
                                std::to_string(options.resolution_degrees) + " degrees apart");
  const double check_radians = check_degrees * degree;
  const AngleGrid grid{n, two_pi / static_cast<double>(n), options.torus};

  ArmGridPlan plan;
  plan.cells_per_axis = static_cast<std::size_t>(n);
  plan.check_degrees = check_degrees;
  const ArmCollisionChecker checker(problem);
  const auto finish = [&](ArmGridPlan& p) {
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return p;
  };
  for (const auto* end : {&query.start, &query.goal})
    if (const auto contact = checker.first_contact(*end)) {
      plan.why_not = std::string(end == &query.start ? "the start" : "the goal") + " collides: " + contact->describe();
      return finish(plan);
    }

  std::vector<GridAxis> axes(joints, GridAxis{n, options.torus ? AxisKind::wrapping : AxisKind::bounded, grid.step});
  GridGraph g(axes, Connectivity::axis_aligned, StepCost::sum_of_axes, [&](std::span<const GridCoordinate> at) {
    JointAngles q(at.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = grid.angle(at[i]);
    return checker.is_free(q);
  });
  if (!options.lazy) {
    if (g.cell_count() > (std::uint64_t{1} << 24))
      throw std::invalid_argument("eager evaluation of " + std::to_string(g.cell_count()) +
                                  " cells is too much (at most 2^24); use lazy evaluation");
    g.evaluate_all();
  }
  // A move is checked once whichever side the search sees it from (moves on an axis of >= 3 cells
  // are identified by their two cells).
  std::unordered_map<std::pair<GridCell, GridCell>, bool, boost::hash<std::pair<GridCell, GridCell>>> moves;
  g.set_move_test([&](GridCell a, GridCell b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = moves.try_emplace({key.first, key.second}, false);
    if (inserted) it->second = motion_is_free(checker, grid.configuration(g, a), grid.configuration(g, b), check_radians);
    return it->second;
  });

  std::size_t joins_checked = 0;
  const Join start = join_to_grid(g, grid, checker, query.start, check_radians, joins_checked);
  const Join goal = join_to_grid(g, grid, checker, query.goal, check_radians, joins_checked);
  const auto record_counts = [&] {
    plan.cells_evaluated = g.cells_evaluated();
    plan.moves_checked = moves.size() + joins_checked;
    if (options.keep_cspace && joints == 2) {
      plan.cspace.resize(g.cell_count());
      for (GridCell c = 0; c < g.cell_count(); ++c) plan.cspace[c] = static_cast<std::uint8_t>(g.state(c));
    }
  };
  if (!start.found || !goal.found) {
    plan.why_not = std::string("no grid cell next to the ") + (start.found ? "goal" : "start") +
                   " is reached from it by a free motion; try a finer resolution";
    record_counts();
    return finish(plan);
  }

  const auto result =
      shortest_path(g, start.cell, goal.cell, options.search, GridDistanceTo(g, goal.cell, GridMetric::sum_of_axes), GridMoveCost{&g});
  plan.expanded = result.expanded;
  plan.generated = result.generated;
  record_counts();
  if (!result.found) {
    plan.why_not = std::string("start and goal are not connected on the ") + (options.torus ? "torus" : "interval") +
                   " grid at " + std::to_string(options.resolution_degrees) + " degrees";
    return finish(plan);
  }
  plan.found = true;
  plan.path.push_back(normalized(query.start));
  for (const GridCell c : result.path) plan.path.push_back(grid.configuration(g, c));
  plan.path.push_back(normalized(query.goal));
  // A start or goal exactly on its cell would repeat it.
  plan.path.erase(std::unique(plan.path.begin(), plan.path.end()), plan.path.end());
  plan.length = arm_path_length(plan.path, options.torus);
  return finish(plan);
}

}  // namespace polyplan
