#include <polyplan/incremental/discovering_robot.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/changing_grid.hpp>
#include <polyplan/search/incremental_search.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

namespace polyplan {
namespace {

constexpr std::array<std::pair<ReplanAlgorithm, std::string_view>, 3> algorithm_names{{
    {ReplanAlgorithm::dstar_lite, "dstar-lite"},
    {ReplanAlgorithm::lpastar, "lpastar"},
    {ReplanAlgorithm::astar, "astar"},
}};

template <IncrementalDirection Direction>
using GridSearch = IncrementalSearch<GridGraph, ChangingGridCosts, ChangingGridDistance, Direction>;

std::string action_word(OpenListAction action) {
  switch (action) {
    case OpenListAction::added: return "add";
    case OpenListAction::rekeyed: return "readd";
    case OpenListAction::removed: return "remove";
    case OpenListAction::unchanged: break;
  }
  return "";
}

std::string state_word(Consistency state) { return state == Consistency::overconsistent ? "over" : "under"; }

// Passes of a search, in cells, for a ReplanTrace.
template <class Search>
class TraceAdapter : public IncrementalObserver<Search> {
 public:
  TraceAdapter(const ChangingGrid& grid, ReplanTrace& trace) : grid_(&grid), trace_(&trace) {}
  void begin(std::size_t replan) {
    replan_ = replan;
    pass_ = 0;
  }
  void step(const Search& search, const IncrementalStep<GridCell, OctileLength>& s) override {
    using Kind = IncrementalStep<GridCell, OctileLength>::Kind;
    ReplanTracePass pass;
    pass.replan = replan_;
    pass.pass = ++pass_;
    pass.popped = point(s.popped);
    pass.key_first = s.key.first;
    pass.key_second = s.key.second;
    pass.g_before = s.g_before;
    pass.g_after = s.g_after;
    pass.rhs = s.rhs;
    pass.h = search.heuristic(s.popped);
    if (const auto parent = search.backpointer(s.popped)) pass.backpointer = point(*parent);
    pass.kind = s.kind == Kind::overconsistent ? "over" : s.kind == Kind::underconsistent ? "under" : "stale key";
    for (const auto& u : s.updated) pass.updated.push_back({point(u.vertex), u.g, u.rhs, action_word(u.action)});
    for (const auto& e : search.open_list())
      pass.open.push_back({point(e.vertex), e.g, e.rhs, e.key.first, e.key.second, state_word(e.state)});
    trace_->pass(pass);
  }

 private:
  GridPoint point(GridCell c) const { return {grid_->x(c), grid_->y(c)}; }
  const ChangingGrid* grid_;
  ReplanTrace* trace_;
  std::size_t replan_ = 0, pass_ = 0;
};

// One algorithm behind the robot's loop: told where the robot is and what changed, asked to plan.
class Replanner {
 public:
  virtual ~Replanner() = default;
  virtual void moved(GridCell at) = 0;
  virtual void changed(const std::vector<ChangedMove>& moves) = 0;
  // False when `until` came first: the plan is not made, and the drive ends.
  virtual bool replan(std::size_t replan, std::optional<std::chrono::steady_clock::time_point> until) = 0;
  virtual OctileLength cost_from(GridCell at) const = 0;
  virtual OctileLength rhs(GridCell at) const = 0;
  virtual std::vector<GridCell> path_from(GridCell at) const = 0;
  virtual const IncrementalCounts& counts() const = 0;
};

// Of two cells, whether the first is strictly nearer the goal in a straight line (squared
// distances between centres, exact): the drive's tie break, a geometric rule any implementation
// can follow. (gonum's DStarLite.Step breaks ties by the neighbours' rhs, then by its iteration
// order; on its nine test cases this rule drives the drives its tests expect.)
struct NearerGoal {
  const ChangingGrid* grid;
  int goal_x, goal_y;
  std::int64_t squared(GridCell c) const {
    const std::int64_t dx = grid->x(c) - goal_x, dy = grid->y(c) - goal_y;
    return dx * dx + dy * dy;
  }
  bool operator()(GridCell a, GridCell b) const { return squared(a) < squared(b); }
};

// Every algorithm searches from the goal towards the robot, so g(at) is the robot's cost to go and
// path_to_root(at) its route; the grid's costs are symmetric, which LPA* (whose edges point away
// from its root) needs for that.
template <IncrementalDirection Direction>
class SearchReplanner : public Replanner {
 public:
  SearchReplanner(const ChangingGrid& grid, GridCell start, GridCell goal, ReplanAlgorithm algorithm,
                  ReplanTrace* trace)
      : search_(grid.graph(), {&grid}, {&grid}, Direction == IncrementalDirection::from_goal ? start : goal,
                Direction == IncrementalDirection::from_goal ? goal : start),
        algorithm_(algorithm), at_(start), nearer_goal_{&grid, grid.x(goal), grid.y(goal)} {
    if (trace) {
      adapter_ = std::make_unique<TraceAdapter<Search>>(grid, *trace);
      search_.set_observer(adapter_.get());
    }
  }
  void moved(GridCell at) override {
    at_ = at;
    if constexpr (Direction == IncrementalDirection::from_goal) search_.move_start(at);  // k_m, lazily
  }
  void changed(const std::vector<ChangedMove>& moves) override {
    if (algorithm_ == ReplanAlgorithm::astar) return;  // it forgets everything anyway
    for (const ChangedMove& m : moves) search_.edge_changed(m.from, m.to, m.old_cost);
  }
  bool replan(std::size_t replan, std::optional<std::chrono::steady_clock::time_point> until) override {
    if (adapter_) adapter_->begin(replan);
    if (algorithm_ == ReplanAlgorithm::astar) {
      search_.restart();
    } else if constexpr (Direction == IncrementalDirection::from_start) {
      if (search_.goal() != at_) search_.move_goal(at_);  // every queued key recomputed
    }
    search_.compute_shortest_path(until);
    return !search_.stopped();
  }
  OctileLength cost_from(GridCell at) const override { return search_.g(at); }
  OctileLength rhs(GridCell at) const override { return search_.rhs(at); }
  std::vector<GridCell> path_from(GridCell at) const override { return search_.path_to_root(at, nearer_goal_); }
  const IncrementalCounts& counts() const override { return search_.counts(); }

 private:
  using Search = GridSearch<Direction>;
  Search search_;
  ReplanAlgorithm algorithm_;
  GridCell at_;
  NearerGoal nearer_goal_;
  std::unique_ptr<TraceAdapter<Search>> adapter_;
};

std::unique_ptr<Replanner> make_replanner(const ChangingGrid& grid, GridCell start, GridCell goal,
                                          const ReplanOptions& options) {
  // LPA* grows from its start: its root is the robot's goal, the robot's cell the goal it aims at.
  if (options.algorithm == ReplanAlgorithm::lpastar)
    return std::make_unique<SearchReplanner<IncrementalDirection::from_start>>(grid, start, goal, options.algorithm,
                                                                               options.trace);
  return std::make_unique<SearchReplanner<IncrementalDirection::from_goal>>(grid, start, goal, options.algorithm,
                                                                            options.trace);
}

void check_cell(const GridMap& map, GridPoint p, const char* what) {
  const std::string at = std::string(what) + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
  if (p.x < 0 || p.y < 0 || p.x >= map.width || p.y >= map.height)
    throw InputError(map.source + ": the " + at + " is outside the " + std::to_string(map.width) + " x " +
                     std::to_string(map.height) + " map");
  if (map.is_blocked(p.x, p.y)) throw InputError(map.source + ": the " + at + " is a blocked cell");
}

// The bytes a drive's tables take per cell of the map: ≈ 75 measured (replan on open maps of
// 1000² and 2000² cells, peak resident memory), rounded up.
constexpr double kBytesPerCell = 96;

void check_options(const ReplanOptions& options, const GridMap& truth) {
  if (!(options.memory_mb > 0) || !(options.time_limit >= 0))
    throw InputError("the memory budget and the time limit: expected a positive number and a number >= 0");
  const double cells = static_cast<double>(truth.width) * truth.height, needed = cells * kBytesPerCell / 1e6;
  if (needed > options.memory_mb)
    throw InputError(truth.source + ": a drive through " + std::to_string(truth.width) + " x " +
                     std::to_string(truth.height) + " cells needs about " + detail::show_number(needed) +
                     " MB, more than the memory budget of " + detail::show_number(options.memory_mb) +
                     " MB (memory-mb)");
  const double r = options.sensor_radius;
  const bool one = smallest_sensor_radius(options.grid) == 1.0;
  if (!std::isfinite(r) || (one ? r < 1.0 : r * r < 2.0))
    throw InputError(std::string("sensor radius: must be a finite number of at least ") +
                     (one ? "1" : "√2 ≈ 1.41421357") + " (the robot must see every cell its next move touches), got " +
                     std::to_string(r));
}

// What the robot knows, and the grid it plans on (unknown cells free).
struct Knowledge {
  Knowledge(int width, int height, const GridConventions& conventions)
      : grid(width, height, conventions), cells(static_cast<std::size_t>(width) * height, CellKnowledge::unknown),
        seen_after(cells.size(), never_seen) {}
  // The whole truth as it is now, known before the first move (no search has run yet: the moves
  // that changed are no news to anyone).
  void learn_all(const GridMap& truth) {
    std::vector<ChangedMove> ignored;
    for (int y = 0; y < grid.height(); ++y)
      for (int x = 0; x < grid.width(); ++x) {
        const GridCell c = grid.cell(x, y);
        const bool blocked = truth.is_blocked(x, y);
        cells[c] = blocked ? CellKnowledge::blocked : CellKnowledge::free;
        seen_after[c] = 0;
        grid.set_blocked(c, blocked, ignored);
        ignored.clear();
      }
  }
  // Senses the cells within `radius` of `at`; returns how many cells changed their believed state
  // and appends the moves that changed. A disc that holds the whole map senses nothing new when
  // it held it before and the truth has not changed since: those senses are skipped (a robot that
  // sees a 2048 x 2048 raster would read 4 million cells at every move).
  // A sense of the whole of a fine raster takes a long time (0.2 s for 1000 x 1000 cells): it stops
  // at `until`, the clock read every 8 rows (a millisecond or two), with `stopped` set, and the drive
  // ends there.
  std::size_t sense(const GridMap& truth, bool truth_changed, GridPoint at, double radius, std::size_t moves,
                    std::vector<ChangedMove>& changed, std::optional<std::chrono::steady_clock::time_point> until,
                    bool& stopped) {
    const double far_x = std::max(at.x, grid.width() - 1 - at.x), far_y = std::max(at.y, grid.height() - 1 - at.y);
    const bool whole_map = far_x * far_x + far_y * far_y <= radius * radius;
    if (whole_map && knows_whole_map && !truth_changed) return 0;
    knows_whole_map = whole_map;
    std::size_t changed_cells = 0;
    // The square of cells the disc reaches, cut to the map (a radius beyond the map's diagonal
    // sees the whole map at the cost of its cells, not of the square).
    const int reach = static_cast<int>(std::min(std::floor(radius), static_cast<double>(grid.width() + grid.height())));
    const int first_row = std::max(0, at.y - reach);
    for (int y = first_row; y <= std::min(grid.height() - 1, at.y + reach); ++y) {
      if (until && (y - first_row) % 8 == 7 && std::chrono::steady_clock::now() >= *until) {
        stopped = true;
        break;
      }
      for (int x = std::max(0, at.x - reach); x <= std::min(grid.width() - 1, at.x + reach); ++x) {
        const std::int64_t dx = x - at.x, dy = y - at.y;
        if (static_cast<double>(dx * dx + dy * dy) > radius * radius) continue;
        const bool blocked = truth.is_blocked(x, y);
        const GridCell c = grid.cell(x, y);
        cells[c] = blocked ? CellKnowledge::blocked : CellKnowledge::free;
        if (seen_after[c] == never_seen) seen_after[c] = moves;
        changed_cells += grid.set_blocked(c, blocked, changed);
      }
    }
    return changed_cells;
  }
  ChangingGrid grid;
  std::vector<CellKnowledge> cells;
  std::vector<std::size_t> seen_after;
  bool knows_whole_map = false;  // the last sense held the whole map
};

}  // namespace

std::string_view to_string(ReplanAlgorithm algorithm) {
  for (const auto& [value, name] : algorithm_names)
    if (value == algorithm) return name;
  return "unknown";
}

std::optional<ReplanAlgorithm> replan_algorithm_from_string(std::string_view name) {
  for (const auto& [value, text] : algorithm_names)
    if (text == name) return value;
  return std::nullopt;
}

std::vector<std::pair<std::string, ReplanAlgorithm>> replan_algorithm_choices() {
  std::vector<std::pair<std::string, ReplanAlgorithm>> choices;
  for (const auto& [value, name] : algorithm_names) choices.emplace_back(std::string(name), value);
  return choices;
}

ReplanAlgorithm parse_replan_algorithm(std::string_view name, const std::string& what) {
  if (const auto algorithm = replan_algorithm_from_string(name)) return *algorithm;
  std::string known;
  for (const auto& [value, text] : algorithm_names) known += (known.empty() ? "" : ", ") + std::string(text);
  throw InputError(what + ": unknown algorithm \"" + std::string(name) + "\" (" + known + ")");
}

double smallest_sensor_radius(const GridConventions& grid) {
  return grid.connectivity == Connectivity::axis_aligned || grid.corner_cutting ? 1.0 : std::sqrt(2.0);
}

void trace_tables(ReplanTrace& trace, const Replanner& replanner, std::size_t replan, std::size_t cells) {
  ReplanTables tables{replan, {}, {}};
  tables.g.reserve(cells);
  tables.rhs.reserve(cells);
  for (GridCell c = 0; c < cells; ++c) {
    tables.g.push_back(replanner.cost_from(c));
    tables.rhs.push_back(replanner.rhs(c));
  }
  trace.tables(tables);
}

ReplanResult drive_through_unknown_map(GridMap truth, GridPoint start, GridPoint goal, const ReplanOptions& options) {
  check_options(options, truth);
  const Stopwatch clock;
  // The limit as a time on the steady clock, for the searches to stop at (a limit of more than 30
  // years is none: the clock's nanoseconds would overflow).
  std::optional<std::chrono::steady_clock::time_point> until;
  if (options.time_limit > 0 && options.time_limit < 1e9)
    until = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                   std::chrono::duration<double>(options.time_limit));
  check_cell(truth, start, "start");
  check_cell(truth, goal, "goal");
  Knowledge known(truth.width, truth.height, options.grid);
  if (options.known_map) known.learn_all(truth);
  const GridCell goal_cell = known.grid.cell(goal.x, goal.y);
  GridCell at = known.grid.cell(start.x, start.y);
  const auto replanner = make_replanner(known.grid, at, goal_cell, options);
  const std::size_t limit = options.max_moves ? options.max_moves : 4 * known.cells.size();

  ReplanResult result;
  result.algorithm = options.algorithm;
  result.traversed = {start};
  std::vector<ChangedMove> changed;
  // The route planned from where the robot is; without a change it still holds, its head dropped.
  std::vector<GridCell> route;
  std::size_t along = 0;
  for (;;) {
    const GridPoint here{known.grid.x(at), known.grid.y(at)};
    const bool truth_changed = options.world_changes && options.world_changes(result.moves, truth);
    changed.clear();
    bool stopped = false;
    ReplanStep step{
        here,
        {},
        0,
        known.sense(truth, truth_changed, here, options.sensor_radius, result.moves, changed, until, stopped),
        false};
    if (stopped) {
      result.status = PlanStatus::limit;
      result.timed_out = true;
      break;
    }
    if (at == goal_cell) {
      result.status = PlanStatus::solved;
      break;
    }
    if (result.replans == 0 || !changed.empty()) {
      const auto began = std::chrono::steady_clock::now();
      const std::size_t expanded = replanner->counts().expanded;
      if (options.trace) options.trace->replan_begins(result.replans + 1, here, step.changed_cells);
      replanner->changed(changed);
      const bool in_time = replanner->replan(++result.replans, until);
      result.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      if (!in_time) {
        result.status = PlanStatus::limit;
        result.timed_out = true;
        break;
      }
      if (options.trace && options.trace->wants_tables())  // not timed: the tables are the caller's
        trace_tables(*options.trace, *replanner, result.replans, known.cells.size());
      step.replanned = true;
      step.expanded = replanner->counts().expanded - expanded;
      route = replanner->path_from(at);
      along = 0;
      result.last_plan.clear();
      for (const GridCell c : route) result.last_plan.push_back({known.grid.x(c), known.grid.y(c)});
    }
    step.cost_to_goal = replanner->cost_from(at);
    result.steps.push_back(step);
    if (step.cost_to_goal == OctileLength::infinity()) {
      result.status = PlanStatus::no_path;
      result.last_plan.clear();
      break;
    }
    if (result.moves == limit || (options.time_limit > 0 && clock.seconds() > options.time_limit)) {
      result.status = PlanStatus::limit;
      result.timed_out = result.moves != limit;
      break;
    }
    const GridCell next = route[++along];
    result.traversed_cost = result.traversed_cost + known.grid.cost(at, next);
    at = next;
    ++result.moves;
    result.traversed.push_back({known.grid.x(at), known.grid.y(at)});
    replanner->moved(at);
  }
  result.found = result.status == PlanStatus::solved;
  const IncrementalCounts& counts = replanner->counts();
  result.expanded = counts.expanded;
  result.generated = counts.generated;
  result.heap_operations = counts.heap_operations();
  result.grid = options.grid;
  result.known_map = options.known_map;
  result.width = truth.width;
  result.height = truth.height;
  result.knowledge = std::move(known.cells);
  result.seen_after = std::move(known.seen_after);
  result.truth = std::move(truth);
  return result;
}

}  // namespace polyplan
