#include <polyplan/arm/arm_grid_planner.hpp>

#include <polyplan/arm/arm_facts.hpp>
#include <polyplan/arm/arm_goal_set.hpp>
#include <polyplan/arm/arm_grid_search.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/grid_graph.hpp>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
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

  JointAngles configuration(std::span<const GridCoordinate> at) const {
    JointAngles q(at.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = angle(at[i]);
    return q;
  }
  JointAngles configuration(const GridGraph& g, GridCell c) const { return configuration(g.coordinates(c)); }

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
// sum of the joints' distances), that is free and reached by a free motion. Its coordinates, or
// nothing.
std::optional<std::vector<GridCoordinate>> join_to_grid(const AngleGrid& grid, const ArmCollisionChecker& checker,
                                                        const JointAngles& q, MotionTally& motions) {
  const std::size_t joints = q.size();
  std::vector<std::array<GridCoordinate, 2>> options(joints);
  for (std::size_t i = 0; i < joints; ++i) options[i] = grid.around(q[i]);
  std::vector<std::pair<double, std::vector<GridCoordinate>>> candidates;
  for (std::uint32_t mask = 0; mask < (1u << joints); ++mask) {
    double distance = 0;
    std::vector<GridCoordinate> at(joints);
    for (std::size_t i = 0; i < joints; ++i) {
      at[i] = options[i][(mask >> i) & 1u];
      distance +=
          grid.torus ? angular_distance(q[i], grid.angle(at[i])) : std::fabs(normalize_angle(q[i]) - grid.angle(at[i]));
    }
    candidates.emplace_back(distance, std::move(at));
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const auto& [distance, at] : candidates) {
    const JointAngles cell = grid.configuration(at);
    if (checker.is_free(cell) && motions.certify(checker, q, cell)) return at;
  }
  return std::nullopt;
}

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// The cells a step of `degrees` makes of the circle: nothing unless it divides 360 into at least 3.
std::optional<std::int64_t> cells_on_the_circle(double degrees) {
  const double cells = 360.0 / degrees;
  if (!(degrees > 0) || !(cells <= 1 << 30)) return std::nullopt;
  const auto n = static_cast<std::int64_t>(std::llround(cells));
  if (n < 3 || std::fabs(cells - static_cast<double>(n)) > 1e-9 * cells) return std::nullopt;
  return n;
}

std::int64_t cells_per_axis(double degrees) {
  if (!(degrees > 0) || !(360.0 / degrees <= 1 << 30))
    throw std::invalid_argument("the grid resolution " + number_text(degrees) +
                                " degrees is not a positive angle of at least 360/2^30 degrees");
  if (const auto n = cells_on_the_circle(degrees)) return *n;
  throw std::invalid_argument("the grid resolution " + number_text(degrees) +
                              " degrees must divide 360 into at least 3 cells");
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
    : problem_(&problem), options_(options), cells_per_axis_(cells_per_axis(options.resolution_degrees)),
      checker_(problem) {
  if (problem.arm.joints() > GridGraph::max_dimensions)
    throw std::invalid_argument("an arm of " + std::to_string(problem.arm.joints()) +
                                " joints needs a grid of as many axes; it has at most " +
                                std::to_string(GridGraph::max_dimensions));
  const double cells = std::pow(static_cast<double>(cells_per_axis_), static_cast<double>(problem.arm.joints()));
  if (!(cells < 0x1p62))
    throw std::invalid_argument("a grid of " + number_text(cells) + " cells (" + std::to_string(cells_per_axis_) +
                                " per joint, " + std::to_string(problem.arm.joints()) +
                                " joints) is too many to number; use a coarser resolution");
  if (!options_.lazy && cells > static_cast<double>(std::uint64_t{1} << 24))
    throw std::invalid_argument("eager evaluation of " + number_text(cells) +
                                " cells is too much (at most 2^24); use lazy evaluation");
  if (options_.coarse_degrees != 0) cells_per_axis(options_.coarse_degrees);  // the same rule: it divides 360
  if (options_.corridor < 0 || options_.widenings < 0)
    throw std::invalid_argument("the corridor's half-width and the number of widenings must not be negative");
  if (!(options_.memory_mb > 0 && options_.memory_mb <= 1e7))
    throw std::invalid_argument("the memory budget memory-mb must be a number of megabytes in (0, 1e+07]");
}

namespace {

// What a query asks of the grid: a path from its start to any one of its goal configurations (its
// goal set, normalised), which the path then ends at exactly.
struct GridQuery {
  const JointAngles& start;
  const std::vector<JointAngles>& goals;
};

// The cells a level's goals join: the search's goals, and which of the query's goals each joins.
struct GoalCells {
  std::vector<std::vector<GridCoordinate>> cells;
  std::vector<std::size_t> goal_of;
};

// Each goal joined to the grid as the start is (join_to_grid), in order; a goal that joins no cell
// is left out.
GoalCells join_goals(const AngleGrid& grid, const ArmCollisionChecker& checker, const std::vector<JointAngles>& goals,
                     MotionTally& motions) {
  GoalCells joined;
  for (std::size_t i = 0; i < goals.size(); ++i)
    if (auto cell = join_to_grid(grid, checker, goals[i], motions)) {
      joined.cells.push_back(std::move(*cell));
      joined.goal_of.push_back(i);
    }
  return joined;
}

// What every way of searching the grid shares: the query's report and its counts.
struct Planning {
  const ArmCollisionChecker& checker;
  const ArmGridOptions& options;
  const AngleGrid& grid;
  const QueryOptions& record;
  std::size_t joints;
  PlanReport<JointAngles>& report;
  MotionTally& motions;
  std::size_t cells_evaluated = 0, expanded = 0, generated = 0, moves_by_clearance = 0;
  double peak_mb = 0;
  std::size_t goal_reached = 0;  // which of the query's goals the path ends at

  // The query stopped at its memory budget after `what` (`context`: what came before, if anything).
  void stop_at_budget(const std::string& what, const std::string& context = "") {
    report.fail(PlanStatus::limit, context + "stopped after " + what + ": the memory budget of one query is " +
                                       number_text(options.memory_mb) +
                                       " MB (option memory-mb: raise it with --memory-mb N)");
    report.facts.set(QueryFacts::stopped_by, "memory limit");
  }
  std::string no_join(bool start_joined, std::size_t goals) const {
    const std::string end =
        start_joined ? (goals == 1 ? "goal" : "any of the " + std::to_string(goals) + " goals") : "start";
    return "no grid cell next to the " + end + " is reached from it by a certified free motion; try a finer resolution";
  }
  // With options.record and two joints, the C-space grid as the search left it (cell k centred on
  // the angle k·step), for the picture.
  template <class StateOf>
  void keep_cells(StateOf state_of) {
    if (!record.record || joints != 2) return;
    auto cells = std::make_shared<CellGrid>();
    cells->columns = cells->rows = static_cast<std::size_t>(grid.n);
    cells->x0 = cells->y0 = -grid.step / 2;
    cells->cell_width = cells->cell_height = grid.step;
    cells->wraps = options.torus;
    cells->states.reserve(static_cast<std::size_t>(grid.n * grid.n));
    for (GridCoordinate y = 0; y < grid.n; ++y)
      for (GridCoordinate x = 0; x < grid.n; ++x) cells->states.push_back(static_cast<std::uint8_t>(state_of(x, y)));
    report.recording.cells = std::move(cells);
  }
  std::string not_connected(std::size_t goals) const {
    const std::string ends = goals == 1 ? "start and goal are not connected"
                                        : "the start is connected to none of its " + std::to_string(goals) + " goals";
    return ends + " on the " + (options.torus ? "torus" : "interval") + " grid at " +
           number_text(options.resolution_degrees) + " degrees";
  }
  void keep_path(const GridQuery& query, const std::vector<std::vector<GridCoordinate>>& cells, std::size_t goal) {
    report.succeed();
    goal_reached = goal;
    report.path.push_back(normalize_angles(query.start));
    for (const auto& c : cells) report.path.push_back(grid.configuration(c));
    report.path.push_back(query.goals[goal]);
    // A start or goal exactly on its cell would repeat it.
    report.path.erase(std::unique(report.path.begin(), report.path.end()), report.path.end());
    report.length = arm_path_length(report.path, options.torus);
    report.certificate = {true, "conservative advancement (every motion certified free by clearance bounds)"};
  }
};

// search/'s shortest_path_to_any on GridGraph, with a move test that certifies each motion: every
// search algorithm, and eager evaluation. Its hash maps cost about 330 bytes a cell. A*'s heuristic
// is the distance to the nearest goal cell.
void plan_on_grid_graph(Planning& p, const GridQuery& query) {
  constexpr double bytes_per_cell = 330;
  const auto max_cells = static_cast<std::size_t>(p.options.memory_mb * 1e6 / bytes_per_cell);
  const AngleGrid& grid = p.grid;
  std::vector<GridAxis> axes(p.joints,
                             GridAxis{grid.n, p.options.torus ? AxisKind::wrapping : AxisKind::bounded, grid.step});
  struct BudgetReached {};  // thrown from the cell test, out of the search, when the budget is spent
  std::size_t cells_tested = 0;
  GridGraph g(axes, Connectivity::axis_aligned, StepCost::sum_of_axes, [&](std::span<const GridCoordinate> at) {
    if (++cells_tested > max_cells) throw BudgetReached{};
    return p.checker.is_free(grid.configuration(at));
  });
  // A move is certified once whichever side the search sees it from (moves on an axis of >= 3
  // cells are identified by their two cells).
  std::unordered_map<std::pair<GridCell, GridCell>, bool, boost::hash<std::pair<GridCell, GridCell>>> moves;
  g.set_move_test([&](GridCell a, GridCell b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = moves.try_emplace({key.first, key.second}, false);
    if (inserted) it->second = p.motions.certify(p.checker, grid.configuration(g, a), grid.configuration(g, b));
    return it->second;
  });
  const auto keep_cells = [&]() {
    p.cells_evaluated = g.cells_evaluated();
    p.peak_mb = static_cast<double>(p.cells_evaluated) * bytes_per_cell / 1e6;
    p.keep_cells([&](GridCoordinate x, GridCoordinate y) { return g.state(g.cell({x, y})); });
  };
  std::optional<std::vector<GridCoordinate>> start;
  GoalCells goals;
  std::vector<GridCell> goal_cells;
  SearchResult<GridCell> result;
  try {
    if (!p.options.lazy) g.evaluate_all();
    start = join_to_grid(grid, p.checker, query.start, p.motions);
    goals = join_goals(grid, p.checker, query.goals, p.motions);
    if (start && !goals.cells.empty()) {
      SearchOptions searching = p.options.search;
      searching.record_expanded = p.record.record;
      std::vector<GridDistanceTo> distances;
      for (const auto& cell : goals.cells) {
        goal_cells.push_back(g.cell(cell));
        distances.emplace_back(g, goal_cells.back(), GridMetric::sum_of_axes);
      }
      const auto nearest_goal = [&](GridCell c) {
        double nearest = distances.front()(c);
        for (std::size_t k = 1; k < distances.size(); ++k) nearest = std::min(nearest, distances[k](c));
        return nearest;
      };
      result = shortest_path_to_any(g, g.cell(*start), goal_cells, searching, nearest_goal, GridMoveCost{&g});
    }
  } catch (const BudgetReached&) {
    p.stop_at_budget("evaluating " + std::to_string(max_cells) + " cells (about 330 bytes each)");
    keep_cells();
    return;
  }
  keep_cells();
  if (!start || goals.cells.empty()) {
    p.report.fail(PlanStatus::not_found, p.no_join(start.has_value(), query.goals.size()));
    return;
  }
  p.expanded = result.expanded;
  p.generated = result.generated;
  for (const GridCell c : result.expanded_order) p.report.recording.expanded.push_back(grid.configuration(g, c));
  if (!result.found) {
    p.report.fail(PlanStatus::not_found, p.not_connected(query.goals.size()));
    return;
  }
  std::vector<std::vector<GridCoordinate>> cells;
  for (const GridCell c : result.path) cells.push_back(g.coordinates(c));
  const auto reached = static_cast<std::size_t>(std::find(goal_cells.begin(), goal_cells.end(), result.path.back()) -
                                                goal_cells.begin());
  p.keep_path(query, cells, goals.goal_of[reached]);
  p.report.facts.set(ArmGridFacts::grid_shortest,
                     p.options.search.algorithm == Search::astar || p.options.search.algorithm == Search::dijkstra
                         ? "proved"
                         : "not claimed");
}

// The coarse path's cells, and which fine cells lie within some number of coarse cells of one of
// them (the largest of the joints' distances, the short way round on the torus).
class Corridor {
 public:
  Corridor(std::vector<std::vector<GridCoordinate>> coarse_path, std::int64_t coarse_n, std::int64_t fine_n, bool torus)
      : path_(std::move(coarse_path)), coarse_n_(coarse_n), fine_n_(fine_n), torus_(torus) {}
  void set_radius(int radius) {
    radius_ = radius;
    distance_.clear();
  }
  // The coarse cell nearest to the fine cell x (fine angle x·360/fine_n, in whole coarse steps).
  bool contains(std::span<const GridCoordinate> x) {
    std::uint64_t key = 0;
    std::array<std::int64_t, GridGraph::max_dimensions> c{};
    for (std::size_t i = x.size(); i-- > 0;) {
      c[i] = (2 * std::int64_t{x[i]} * coarse_n_ + fine_n_) / (2 * fine_n_);
      if (c[i] == coarse_n_) c[i] = torus_ ? 0 : coarse_n_ - 1;
      key = key * static_cast<std::uint64_t>(coarse_n_) + static_cast<std::uint64_t>(c[i]);
    }
    auto [it, inserted] = distance_.try_emplace(key, 0);
    if (inserted) {
      std::int64_t best = std::numeric_limits<std::int64_t>::max();
      for (const auto& p : path_) {
        std::int64_t far = 0;
        for (std::size_t i = 0; i < x.size() && far < best; ++i) {
          std::int64_t d = std::abs(c[i] - p[i]);
          if (torus_) d = std::min(d, coarse_n_ - d);
          far = std::max(far, d);
        }
        best = std::min(best, far);
      }
      it->second = best;
    }
    return it->second <= radius_;
  }

 private:
  std::vector<std::vector<GridCoordinate>> path_;
  std::int64_t coarse_n_, fine_n_;
  bool torus_;
  int radius_ = 0;
  std::unordered_map<std::uint64_t, std::int64_t> distance_;
};

void count(Planning& p, const ArmGridSearchResult& r) {
  p.cells_evaluated += r.cells_evaluated;
  p.moves_by_clearance += r.moves_by_clearance;
  p.motions.checked += r.moves_certified;
  p.motions.uncertified += r.moves_uncertified;
  p.peak_mb = std::max(p.peak_mb, static_cast<double>(r.peak_bytes) / 1e6);
}

// A coarse grid's path, to guide a finer search, and how many cells searching its whole grid
// evaluates (or would: predicted from the level above).
struct GuidePath {
  std::vector<std::vector<GridCoordinate>> path;
  std::int64_t n = 0;
  double predicted_cells = 0;
};

// The search of one level's grid (n cells per joint) from the cell the start joins to the cells the
// goals join, and which goal each of those is; nothing when the start or every goal joins no cell.
struct LevelProblem {
  ArmGridSearchProblem search;
  std::vector<std::size_t> goal_of;
};
std::optional<LevelProblem> level_problem(Planning& p, const GridQuery& query, std::int64_t n, bool& start_joined) {
  const AngleGrid grid{n, two_pi / static_cast<double>(n), p.options.torus};
  const auto start = join_to_grid(grid, p.checker, query.start, p.motions);
  start_joined = start.has_value();
  GoalCells goals = join_goals(grid, p.checker, query.goals, p.motions);
  if (!start || goals.cells.empty()) return std::nullopt;
  LevelProblem level;
  level.search.cells_per_axis = n;
  level.search.torus = p.options.torus;
  level.search.start = *start;
  level.search.goals = std::move(goals.cells);
  level.search.use_heuristic = p.options.search.algorithm == Search::astar;
  level.search.memory_bytes = static_cast<std::size_t>(p.options.memory_mb * 1e6);
  level.goal_of = std::move(goals.goal_of);
  return level;
}

// Whether a grid of n cells per joint is searched only near the guide's path: when its whole
// search is predicted (the guide's cells times the cells one guide cell holds) above exact_cells.
std::optional<Corridor> corridor_for(const Planning& p, const std::optional<GuidePath>& guide, std::int64_t n,
                                     double& predicted) {
  predicted = 0;
  if (!guide) return std::nullopt;
  predicted = guide->predicted_cells *
              std::pow(static_cast<double>(n) / static_cast<double>(guide->n), static_cast<double>(p.joints));
  if (predicted <= static_cast<double>(p.options.exact_cells)) return std::nullopt;
  return Corridor(guide->path, guide->n, n, p.options.torus);
}

// The path at `degrees`: its whole grid searched, or, when `guided` and that is predicted too
// costly, only a corridor around the path at twice the step (which is found the same way, up to
// 45 degrees). Only a guide: whether it is the shortest does not matter, only that it finds the way.
std::optional<GuidePath> guide_path(Planning& p, const GridQuery& query, double degrees, bool guided) {
  const std::int64_t n = cells_per_axis(degrees);
  bool start_joined = false;
  auto level = level_problem(p, query, n, start_joined);
  if (!level) return std::nullopt;
  std::optional<GuidePath> coarser;
  if (guided && 2 * degrees <= 45 && cells_on_the_circle(2 * degrees))
    coarser = guide_path(p, query, 2 * degrees, true);
  double predicted = 0;
  std::optional<Corridor> corridor = corridor_for(p, coarser, n, predicted);
  if (corridor) {
    corridor->set_radius(p.options.corridor);
    level->search.in_corridor = [&](std::span<const std::int32_t> x) { return corridor->contains(x); };
  }
  ArmGridSearch search(p.checker, level->search);
  const ArmGridSearchResult found = search.run();
  count(p, found);
  if (!found.found) return std::nullopt;
  return GuidePath{found.path, n, corridor ? predicted : static_cast<double>(found.cells_evaluated)};
}

// The compact lazy search (arm_grid_search.hpp), coarse to fine when the grid is finer than
// options.coarse_degrees.
void plan_compactly(Planning& p, const GridQuery& query) {
  const ArmGridOptions& options = p.options;
  const AngleGrid& grid = p.grid;
  bool start_joined = false;
  auto level = level_problem(p, query, grid.n, start_joined);
  if (!level) {
    p.report.fail(PlanStatus::not_found, p.no_join(start_joined, query.goals.size()));
    return;
  }
  ArmGridSearchProblem& searching = level->search;
  searching.record_expanded = p.record.record;

  // Coarse to fine: the coarse grid's path, when there is one, and only when the whole fine grid
  // is predicted too costly. A guide without a path may have missed a passage narrower than its
  // cells: finer guides are tried, each searched whole (the step halved while it divides 360 and
  // stays coarser than the grid), before the whole fine grid.
  std::optional<Corridor> corridor;
  double guide_degrees = options.coarse_degrees;
  if (options.coarse_degrees > options.resolution_degrees) {
    std::optional<GuidePath> coarse = guide_path(p, query, guide_degrees, true);
    while (!coarse && guide_degrees / 2 > options.resolution_degrees && cells_on_the_circle(guide_degrees / 2))
      coarse = guide_path(p, query, guide_degrees /= 2, false);
    p.report.facts.set(ArmGridFacts::grid_coarse_degrees, guide_degrees);
    if (coarse) {
      double predicted = 0;
      corridor = corridor_for(p, coarse, grid.n, predicted);
      p.report.facts.set(ArmGridFacts::grid_predicted_cells, predicted);
    }
  }

  ArmGridSearch search(p.checker, searching);
  ArmGridSearchResult result;
  int radius = options.corridor, rounds = 0;
  for (;;) {
    if (corridor) {
      corridor->set_radius(radius);
      search.set_corridor([&](std::span<const std::int32_t> x) { return corridor->contains(x); });
    }
    ArmGridSearchResult round = search.run();
    ++rounds;
    p.peak_mb = std::max(p.peak_mb, static_cast<double>(round.peak_bytes) / 1e6);
    // A widened round that runs out of memory leaves the narrower corridor's path standing.
    if (round.over_budget && result.found) break;
    result = std::move(round);
    const bool proved =
        !corridor || (result.found ? result.cost_steps <= result.outside_bound_steps
                                   : result.outside_bound_steps == std::numeric_limits<std::int64_t>::max());
    if (proved || result.over_budget || rounds > options.widenings) break;
    radius *= 2;
  }
  // A corridor that holds no path proves nothing about the grid (the guide may have missed a
  // passage only the fine grid has): the whole grid is searched then, reusing every cell measured,
  // and only the memory budget may stop it — with status limit, never a claim that no path exists.
  const bool corridor_failed = corridor && !result.found && !result.over_budget &&
                               result.outside_bound_steps != std::numeric_limits<std::int64_t>::max();
  if (corridor_failed) {
    search.set_corridor({});
    result = search.run();
    ++rounds;
    p.peak_mb = std::max(p.peak_mb, static_cast<double>(result.peak_bytes) / 1e6);
    p.report.facts.set(ArmGridFacts::grid_whole_grid, true);
  }
  count(p, result);
  p.expanded = result.expanded;
  p.generated = result.generated;
  if (corridor) {
    p.report.facts.set(ArmGridFacts::grid_corridor, radius);
    p.report.facts.set(ArmGridFacts::grid_rounds, rounds);
  }
  for (const auto& c : result.expanded_order) p.report.recording.expanded.push_back(grid.configuration(c));
  p.keep_cells([&](GridCoordinate x, GridCoordinate y) { return search.state(std::array{x, y}); });
  if (result.over_budget) {
    p.stop_at_budget("evaluating " + std::to_string(result.cells_evaluated) + " cells",
                     corridor_failed ? "no path within " + std::to_string(radius) + " coarse cells of the " +
                                           number_text(guide_degrees) + "-degree path; the whole grid's search "
                                     : "");
    return;
  }
  if (!result.found) {
    p.report.fail(PlanStatus::not_found, p.not_connected(query.goals.size()));
    return;
  }
  p.keep_path(query, result.path, level->goal_of[result.goal_reached]);
  const bool proved = result.cost_steps <= result.outside_bound_steps;
  p.report.facts.set(ArmGridFacts::grid_shortest, proved ? "proved" : "corridor");
  if (!proved) {
    const double bound = static_cast<double>(result.outside_bound_steps) * grid.step;
    p.report.facts.set(ArmGridFacts::grid_lower_bound, bound);
    char note[200];
    std::snprintf(
        note, sizeof note,
        "the shortest within %d coarse cells of the %s-degree path; the grid's shortest, not proved, is at least %.6f "
        "rad between the same cells (option coarse 0 searches the whole grid)",
        radius, number_text(guide_degrees).c_str(), bound);
    p.report.facts.set(QueryFacts::note, note);
  }
}

}  // namespace

PlanReport<JointAngles> ArmGridPlanner::plan(const ArmQuery& query, const QueryOptions& record) {
  const Stopwatch planning;
  const std::size_t joints = problem_->arm.joints();
  const std::int64_t n = cells_per_axis_;
  const AngleGrid grid{n, two_pi / static_cast<double>(n), options_.torus};

  PlanReport<JointAngles> report;
  Facts& facts = report.facts;
  facts.set(ArmGridFacts::grid_resolution_degrees, options_.resolution_degrees);
  facts.set(ArmGridFacts::grid_cells_per_axis, n);
  facts.set(ArmGridFacts::grid_torus, options_.torus);
  facts.set(ArmGridFacts::grid_evaluation, options_.lazy ? "lazy" : "eager");
  facts.set(SearchFacts::algorithm, to_string(options_.search.algorithm));
  MotionTally motions;
  Planning p{checker_, options_, grid, record, joints, report, motions};
  if (auto why = query_not_free(checker_, query)) {
    report.fail(PlanStatus::invalid_query, *why);
  } else if (const ArmGoalSet goal_set = arm_goal_set(checker_, query); goal_set.goals.empty()) {
    report.fail(goal_set.status, goal_set.why_none);
  } else {
    if (goal_set.goals.size() > 1) facts.set(GoalFacts::candidates, goal_set.goals.size());
    const std::vector<JointAngles> goals = goal_set.configurations();
    const GridQuery grid_query{query.start, goals};
    const bool compact =
        options_.lazy && (options_.search.algorithm == Search::astar || options_.search.algorithm == Search::dijkstra);
    if (compact) plan_compactly(p, grid_query);
    else plan_on_grid_graph(p, grid_query);
    if (report.found) set_goal_facts(goal_set, p.goal_reached, facts);
  }
  facts.set(ArmGridFacts::cells_evaluated, p.cells_evaluated);
  facts.set(ArmGridFacts::moves_checked, motions.checked);
  facts.set(ArmGridFacts::moves_by_clearance, p.moves_by_clearance);
  facts.set(ArmGridFacts::moves_uncertified, motions.uncertified);
  facts.set(ArmGridFacts::expanded, p.expanded);
  facts.set(SearchFacts::expanded, p.expanded);
  facts.set(SearchFacts::generated, p.generated);
  facts.set(ArmGridFacts::memory_mb, p.peak_mb);
  facts.set(ArmGridFacts::seconds, planning.seconds());
  return report;
}

PlannerEntry<PlanarArm> arm_grid_planner_entry() {
  OptionTable<ArmGridOptions> table;
  table.add("resolution", &ArmGridOptions::resolution_degrees, "grid step in degrees (must divide 360)", above(0));
  table.add("torus", &ArmGridOptions::torus, "joint angles wrap round (false: each joint is the interval [0, 2pi))");
  table.add("evaluation", &ArmGridOptions::lazy,
            "lazy: decide cells when the search reaches them; eager: every cell first",
            std::vector<std::pair<std::string, bool>>{{"lazy", true}, {"eager", false}});
  add_search_options(table, &ArmGridOptions::search);
  table.add(
      "coarse", &ArmGridOptions::coarse_degrees,
      "a finer grid is searched first at this resolution (degrees), then in a corridor around that path; 0: whole grid",
      at_least(0));
  table.add("corridor", &ArmGridOptions::corridor, "the corridor's half-width in coarse cells", at_least(0));
  table.add("exact-cells", &ArmGridOptions::exact_cells,
            "a finer grid is searched whole when the coarse search predicts at most this many cells", at_least(1));
  table.add("widenings", &ArmGridOptions::widenings,
            "times the corridor may double while it cannot prove its path shortest", at_least(0));
  table.add("memory-mb", &ArmGridOptions::memory_mb,
            "the memory one query's tables may take before it stops, saying so",
            OptionRange{0, 1e7, true, false});  // up to 10 TB: its bytes fit a size_t
  return make_planner_entry<PlanarArm, ArmGridOptions>(
      "grid",
      "the course's graph-search homework's grid over the joint angles (a torus), searched lazily; every move a "
      "certified motion",
      std::move(table),
      [](const ArmProblem& problem, const ArmGridOptions& o) { return std::make_unique<ArmGridPlanner>(problem, o); });
}

}  // namespace polyplan
