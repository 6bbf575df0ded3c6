#include <polyplan/arm/arm_grid_planner.hpp>

#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/roadmaps/stopwatch.hpp>
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/grid_graph.hpp>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <optional>
#include <cmath>
#include <cstdio>
#include <memory>
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

// Motions certified for one query, and those refused because no bound proved them free (near
// contact): a refused motion is treated as blocked, never as free.
struct MotionTally {
  std::size_t checked = 0, uncertified = 0;
  bool certify(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to) {
    ++checked;
    const MotionCertificate certificate = certify_motion(checker, from, to);
    uncertified += certificate.verdict == MotionCertificate::Verdict::uncertified;
    return certificate.free();
  }
};

// Where the start (or goal) joins the grid: the first of the cells around it, nearest first (by the
// sum of the joints' distances), that is free and reached by a free motion.
struct Join {
  bool found = false;
  GridCell cell = 0;
};

Join join_to_grid(const GridGraph& g, const AngleGrid& grid, const ArmCollisionChecker& checker, const JointAngles& q,
                  MotionTally& motions) {
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
    if (motions.certify(checker, q, grid.configuration(g, cell))) return {true, cell};
  }
  return {};
}

JointAngles normalized(const JointAngles& q) {
  JointAngles out(q.size());
  std::transform(q.begin(), q.end(), out.begin(), [](double a) { return normalize_angle(a); });
  return out;
}

std::string degrees_text(double degrees) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", degrees);
  return text;
}

std::int64_t cells_per_axis(const ArmGridOptions& options) {
  const double cells = 360.0 / options.resolution_degrees;
  if (!(options.resolution_degrees > 0) || !(cells <= 1 << 30))
    throw std::invalid_argument("the grid resolution " + degrees_text(options.resolution_degrees) +
                                " degrees is not a positive angle of at least 360/2^30 degrees");
  const auto n = static_cast<std::int64_t>(std::llround(cells));
  if (n < 3 ||
      std::fabs(cells - static_cast<double>(n)) > 1e-9 * cells)
    throw std::invalid_argument("the grid resolution " + degrees_text(options.resolution_degrees) +
                                " degrees must divide 360 into at least 3 cells");
  return n;
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

ArmGridPlanner::ArmGridPlanner(const ArmProblem& problem, ArmGridOptions options)
    : problem_(&problem), options_(options), cells_per_axis_(cells_per_axis(options)), checker_(problem) {
  if (problem.arm.joints() > GridGraph::max_dimensions)
    throw std::invalid_argument("an arm of " + std::to_string(problem.arm.joints()) + " joints needs a grid of as many axes; it has at most " +
                                std::to_string(GridGraph::max_dimensions));
  const double cells = std::pow(static_cast<double>(cells_per_axis_), static_cast<double>(problem.arm.joints()));
  if (!options_.lazy && cells > static_cast<double>(std::uint64_t{1} << 24))
    throw std::invalid_argument("eager evaluation of " + degrees_text(cells) + " cells is too much (at most 2^24); use lazy evaluation");
}

PlanReport<JointAngles> ArmGridPlanner::plan(const ArmQuery& query, const QueryOptions& record) {
  const Stopwatch planning;
  const std::size_t joints = problem_->arm.joints();
  const std::int64_t n = cells_per_axis_;
  const AngleGrid grid{n, two_pi / static_cast<double>(n), options_.torus};

  PlanReport<JointAngles> report;
  Facts& facts = report.facts;
  facts.set("grid.resolution_degrees", options_.resolution_degrees);
  facts.set("grid.cells_per_axis", n);
  facts.set("grid.torus", options_.torus);
  facts.set("grid.evaluation", options_.lazy ? "lazy" : "eager");
  facts.set("search.algorithm", to_string(options_.search.algorithm));
  std::size_t cells_evaluated = 0, expanded = 0, generated = 0;
  MotionTally motions;
  const auto finish = [&]() {
    facts.set("cells_evaluated", cells_evaluated);
    facts.set("moves_checked", motions.checked);
    facts.set("moves_uncertified", motions.uncertified);
    facts.set("expanded", expanded);
    facts.set("search.expanded", expanded);
    facts.set("search.generated", generated);
    facts.set("seconds", planning.seconds());
    return report;
  };

  if (auto why = query_not_free(checker_, query)) {
    report.why_not = *why;
    return finish();
  }

  std::vector<GridAxis> axes(joints, GridAxis{n, options_.torus ? AxisKind::wrapping : AxisKind::bounded, grid.step});
  struct BudgetReached {};  // thrown from the cell test, out of the search, when the budget is spent
  std::size_t cells_tested = 0;
  GridGraph g(axes, Connectivity::axis_aligned, StepCost::sum_of_axes, [&](std::span<const GridCoordinate> at) {
    if (++cells_tested > options_.max_cells) throw BudgetReached{};
    JointAngles q(at.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = grid.angle(at[i]);
    return checker_.is_free(q);
  });
  // A move is certified once whichever side the search sees it from (moves on an axis of >= 3
  // cells are identified by their two cells).
  std::unordered_map<std::pair<GridCell, GridCell>, bool, boost::hash<std::pair<GridCell, GridCell>>> moves;
  g.set_move_test([&](GridCell a, GridCell b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = moves.try_emplace({key.first, key.second}, false);
    if (inserted) it->second = motions.certify(checker_, grid.configuration(g, a), grid.configuration(g, b));
    return it->second;
  });
  const auto keep_cells = [&]() {
    cells_evaluated = g.cells_evaluated();
    if (!record.record || joints != 2) return;
    auto cells = std::make_shared<CellGrid>();
    cells->columns = cells->rows = static_cast<std::size_t>(n);
    cells->x0 = cells->y0 = -grid.step / 2;  // cell k is centred on the angle k·step
    cells->cell_width = cells->cell_height = grid.step;
    cells->states.resize(g.cell_count());
    for (GridCell c = 0; c < g.cell_count(); ++c) cells->states[c] = static_cast<std::uint8_t>(g.state(c));
    report.cells = std::move(cells);
  };

  const auto over_budget = [&]() {
    report.why_not = "stopped after evaluating " + std::to_string(options_.max_cells) +
                     " cells, the budget of one query (option max_cells: raise it with --max_cells N, at about 330 bytes a cell)";
    keep_cells();
    return finish();
  };
  try {
    if (!options_.lazy) g.evaluate_all();
  } catch (const BudgetReached&) {
    return over_budget();
  }
  std::optional<Join> start, goal;
  SearchResult<GridCell> result;
  try {
    start = join_to_grid(g, grid, checker_, query.start, motions);
    goal = join_to_grid(g, grid, checker_, query.goal, motions);
    if (start->found && goal->found) {
      SearchOptions searching = options_.search;
      searching.record_expanded = record.record;
      result = shortest_path(g, start->cell, goal->cell, searching, GridDistanceTo(g, goal->cell, GridMetric::sum_of_axes),
                             GridMoveCost{&g});
    }
  } catch (const BudgetReached&) {
    return over_budget();
  }
  if (!start->found || !goal->found) {
    report.why_not = std::string("no grid cell next to the ") + (start->found ? "goal" : "start") +
                     " is reached from it by a certified free motion; try a finer resolution";
    keep_cells();
    return finish();
  }

  expanded = result.expanded;
  generated = result.generated;
  for (const GridCell c : result.expanded_order) report.expanded.push_back(grid.configuration(g, c));
  keep_cells();
  if (!result.found) {
    report.why_not = std::string("start and goal are not connected on the ") + (options_.torus ? "torus" : "interval") +
                     " grid at " + degrees_text(options_.resolution_degrees) + " degrees";
    return finish();
  }
  report.found = true;
  report.path.push_back(normalized(query.start));
  for (const GridCell c : result.path) report.path.push_back(grid.configuration(g, c));
  report.path.push_back(normalized(query.goal));
  // A start or goal exactly on its cell would repeat it.
  report.path.erase(std::unique(report.path.begin(), report.path.end()), report.path.end());
  report.length = arm_path_length(report.path, options_.torus);
  report.certificate = {true, "conservative advancement (every motion certified free by clearance bounds)"};
  return finish();
}

PlannerEntry<PlanarArm> arm_grid_planner_entry() {
  OptionTable<ArmGridOptions> table;
  table.add("resolution", &ArmGridOptions::resolution_degrees, "grid step in degrees (must divide 360)");
  table.add("torus", &ArmGridOptions::torus, "joint angles wrap round (false: each joint is the interval [0, 2pi))");
  table.add("evaluation", &ArmGridOptions::lazy, "lazy: decide cells when the search reaches them; eager: every cell first",
            std::vector<std::pair<std::string, bool>>{{"lazy", true}, {"eager", false}});
  add_search_options(table, &ArmGridOptions::search);
  table.add("max_cells", &ArmGridOptions::max_cells, "cells one query may evaluate before it stops, not found (the memory budget)");
  return make_planner_entry<PlanarArm, ArmGridOptions>(
      "grid", "seed 000's grid over the joint angles (a torus), searched lazily; every move a certified motion",
      std::move(table), [](const ArmProblem& problem, const ArmGridOptions& o) {
        return std::make_unique<ArmGridPlanner>(problem, o);
      });
}

}  // namespace polyplan
