#include <polyplan/incremental/replanning_planner.hpp>

#include <polyplan/plan/grid_options.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_rasterize.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/raster_grid.hpp>
#include <polyplan/incremental/replan_facts.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

// The world once its first `made` changes have happened: the obstacles numbered as the file
// numbers them (the world's, then the added ones), the removed ones gone.
World world_after(const World& world, std::size_t made) {
  std::vector<std::optional<PolygonWithHoles>> obstacles(world.obstacles.begin(), world.obstacles.end());
  std::vector<std::string> names = world.obstacle_names;
  for (std::size_t i = 0; i < made; ++i) {
    const WorldChange& change = world.changes[i];
    if (change.added) {
      obstacles.emplace_back(*change.added);
      names.push_back(change.name + ".add_obstacle");
    }
    if (change.removed) obstacles[*change.removed].reset();
  }
  World after = world;
  after.obstacles.clear();
  after.obstacle_names.clear();
  after.changes.clear();
  for (std::size_t k = 0; k < obstacles.size(); ++k)
    if (obstacles[k]) {
      after.obstacles.push_back(std::move(*obstacles[k]));
      after.obstacle_names.push_back(std::move(names[k]));
    }
  return after;
}

// The obstacles that changes [from, to) add or remove.
std::vector<const PolygonWithHoles*> changed_obstacles(const World& world, std::size_t from, std::size_t to) {
  std::vector<const PolygonWithHoles*> obstacles;  // the world's, then those added, in order
  for (const PolygonWithHoles& o : world.obstacles) obstacles.push_back(&o);
  std::vector<const PolygonWithHoles*> changed;
  for (std::size_t i = 0; i < to; ++i) {
    const WorldChange& change = world.changes[i];
    if (change.added) obstacles.push_back(&*change.added);
    if (i < from) continue;
    if (change.added) changed.push_back(&*change.added);
    if (change.removed) changed.push_back(obstacles[*change.removed]);
  }
  return changed;
}

// The raster of `after`, the world once changes [from, to) of `world` are made too: `before` (the
// raster of the world before them) with only the cells near the changed obstacles decided again —
// a polygon world that changes at every move of a long drive at 2048 cells per axis took minutes
// rasterised whole.
Raster raster_after(const CSpace& after, const Raster& before, const World& world, std::size_t from, std::size_t to) {
  return rasterize_change(after, before, changed_obstacles(world, from, to));
}

// A round world's raster has no such partial update: it is rasterised whole.
Raster raster_after(const RoundWorld& after, const Raster& before, const World&, std::size_t, std::size_t) {
  return rasterize(after, before.cells_per_axis);
}

// The picture draws a changed polygon world's C-space as the drive ended; PlanRecording holds a
// C-space only, so a round world's picture draws the file's world.
void record_world_at_end(const std::shared_ptr<const CSpace>& world, PlanRecording<ExactPoint>& recording) {
  recording.world_at_end = world;
}
void record_world_at_end(const std::shared_ptr<const RoundWorld>&, PlanRecording<ExactPoint>&) {}

// The world between two moments of change: from the move `from_moves` on, `made` changes made.
template <class Problem>
struct Phase {
  std::size_t from_moves = 0, made = 0;
  std::shared_ptr<const Problem> owned;  // none for the planner's own world (the first phase); the picture shares it
  const Problem* problem = nullptr;
  Raster raster;
};

GridMap grid_map(const Raster& raster, const std::string& source) {
  GridMap map;
  map.source = source;
  map.width = map.height = static_cast<int>(raster.cells_per_axis);
  map.blocked.assign(raster.blocked.begin(), raster.blocked.end());  // both x + y·n
  return map;
}

// The registry's name: the algorithm's, but A* is the raster planner's already.
std::string replanning_planner_name(ReplanAlgorithm algorithm) {
  return algorithm == ReplanAlgorithm::astar ? "repeated-astar" : std::string(to_string(algorithm));
}

GridCell cell_of(const Raster& raster, GridPoint p) {
  return static_cast<GridCell>(p.x) + static_cast<GridCell>(p.y) * raster.cells_per_axis;
}

GridPoint point_of(const Raster& raster, GridCell c) {
  return {static_cast<int>(c % raster.cells_per_axis), static_cast<int>(c / raster.cells_per_axis)};
}

}  // namespace

template <class Space>
struct BasicReplanningPlanner<Space>::Impl {
  using Problem = typename Space::Problem;
  const Problem* problem;
  ReplanAlgorithm algorithm;
  ReplanningOptions options;
  std::vector<Phase<Problem>> phases;  // by from_moves; the first is the world as it starts

  Impl(const Problem& p, ReplanAlgorithm a, const ReplanningOptions& o) : problem(&p), algorithm(a), options(o) {
    const bool one = smallest_sensor_radius(o.grid) == 1.0;
    if (o.sensor != 0 && !(std::isfinite(o.sensor) && o.sensor > 0 && (one ? o.sensor >= 1 : o.sensor * o.sensor >= 2)))
      throw std::invalid_argument(std::string("sensor: expected 0 (the whole raster) or a finite number of cells of "
                                              "at least ") +
                                  (one ? "1" : "√2 ≈ 1.41421357") + ", got " + std::to_string(o.sensor));
    phases.push_back({0, 0, nullptr, &p, rasterize(p, o.resolution)});
    const World& world = p.world();
    // One world for each moment of change: the changes listed with one after_moves happen at once.
    for (std::size_t i = 0; i < world.changes.size(); ++i) {
      if (i + 1 < world.changes.size() && world.changes[i + 1].after_moves == world.changes[i].after_moves) continue;
      auto changed = std::make_shared<const Problem>(world_after(world, i + 1));
      Raster raster = raster_after(*changed, phases.back().raster, world, phases.back().made, i + 1);
      const Problem* view = changed.get();
      phases.push_back({world.changes[i].after_moves, i + 1, std::move(changed), view, std::move(raster)});
    }
  }

  double sensor_radius() const {
    const double n = static_cast<double>(phases.front().raster.cells_per_axis);
    return options.sensor != 0 ? options.sensor : std::hypot(n, n) + 1;
  }

  // The drive's cells from move `from` to move `to` (both included), on the raster.
  static std::vector<GridCell> stretch(const Raster& raster, const ReplanResult& drive, std::size_t from,
                                       std::size_t to) {
    std::vector<GridCell> cells;
    for (std::size_t m = from; m <= to; ++m) cells.push_back(cell_of(raster, drive.traversed[m]));
    return cells;
  }

  // start → turns → goal, each stretch between two changes checked exactly in its own world.
  void return_drive(const Query& query, const ReplanResult& drive, std::size_t lived,
                    PlanReport<ExactPoint>& report) const {
    std::vector<ExactPoint> path;
    for (std::size_t p = 0; p < lived; ++p) {
      const Phase<Problem>& phase = phases[p];
      const std::size_t to = p + 1 < lived ? phases[p + 1].from_moves : drive.moves;
      const std::vector<GridCell> cells = stretch(phase.raster, drive, phase.from_moves, to);
      const ExactPoint from_point = p == 0 ? query.start : path.back();
      const ExactPoint to_point =
          p + 1 == lived ? query.goal : phase.raster.cell_center(drive.traversed[to].x, drive.traversed[to].y);
      const std::vector<ExactPoint> piece = polyline_through_turns(phase.raster, from_point, cells, to_point);
      const PathCheck check = check_exactly(*phase.problem, piece);
      if (!check.valid) {
        report.fail(PlanStatus::not_found, "the drive from move " + std::to_string(phase.from_moves) + " to move " +
                                               std::to_string(to) + " is not a valid motion in the world of " +
                                               made_text(phase) + ": " + check.reason);
        return;
      }
      path.insert(path.end(), piece.begin() + (path.empty() ? 0 : 1), piece.end());
    }
    if (path.size() == 1) path.push_back(path.front());  // start = goal: one motion of length 0
    report.succeed();
    report.path = std::move(path);
    report.length = euclidean_length(report.path);
    report.certificate = {true, std::string(exact_check_name(*problem)) +
                                    " of each stretch in the world as it was when driven"};
  }

  static std::string made_text(const Phase<Problem>& phase) {
    if (phase.made == 0) return "the file";
    return phase.made == 1 ? "changes[0]" : "changes[0.." + std::to_string(phase.made - 1) + "]";
  }

  // Why a drive that did not reach the goal ended.
  static void report_stop(const ReplanResult& drive, const Phase<Problem>& last, PlanReport<ExactPoint>& report) {
    const GridPoint at = drive.traversed.back();
    const std::string cell = cell_text(static_cast<std::size_t>(at.x), static_cast<std::size_t>(at.y));
    const std::string after = "after " + std::to_string(drive.moves) + " moves";
    if (drive.status == PlanStatus::limit) {
      const std::string limit = drive.timed_out ? "time limit" : "move limit";
      report.facts.set(QueryFacts::stopped_by, limit);
      report.fail(PlanStatus::limit, after + ": the " + limit + " ended the drive at cell " + cell);
    } else if (drive.truth.is_blocked(at.x, at.y)) {
      report.fail(PlanStatus::not_found,
                  after + ", the world of " + made_text(last) + " blocks the robot's own cell " + cell);
    } else {
      const std::string n = std::to_string(last.raster.cells_per_axis);
      report.fail(PlanStatus::not_found, after + ", no path on the " + n + " x " + n +
                                             " grid the robot knows from cell " + cell + " to the goal's cell");
    }
  }

  void record_facts(const ReplanResult& drive, std::size_t lived, Facts& facts) const {
    facts.set(ReplanFacts::moves, drive.moves);
    facts.set(ReplanFacts::replans, drive.replans);
    facts.set(ReplanFacts::changes_made, phases[lived - 1].made);
    facts.set(ReplanFacts::grid_cost, drive.grid.in_cells(drive.traversed_cost));
    facts.set(SearchFacts::expanded, drive.expanded);
    facts.set(SearchFacts::generated, drive.generated);
    facts.set(SearchFacts::heap_operations, drive.heap_operations);
    facts.set(SearchFacts::seconds, drive.seconds);
  }

  // The drive's options, its world changing to each phase's raster as the moves reach it; `lived`
  // counts the phases the drive has seen. `spent`: the query's seconds before the drive, which
  // its time limit counts too.
  ReplanOptions drive_options(std::size_t& lived, double spent) const {
    ReplanOptions replanning;
    replanning.algorithm = algorithm;
    replanning.sensor_radius = sensor_radius();
    replanning.max_moves = options.max_moves;
    replanning.grid = options.grid;
    replanning.known_map = options.known_map;
    replanning.time_limit = std::max(options.time - spent, 1e-9);  // 0 would be none
    replanning.world_changes = [this, &lived](std::size_t moves, GridMap& truth) {
      const std::size_t before = lived;
      for (; lived < phases.size() && phases[lived].from_moves <= moves; ++lived)
        truth.blocked.assign(phases[lived].raster.blocked.begin(), phases[lived].raster.blocked.end());
      return lived != before;
    };
    return replanning;
  }

  void record_start(Facts& facts) const {
    const Raster& first = phases.front().raster;
    facts.set(RoadmapFacts::kind, replanning_planner_name(algorithm));
    facts.set(RasterFacts::cells_per_axis, first.cells_per_axis);
    facts.set(RasterFacts::blocked_cells, first.blocked_count());
    record_grid_conventions(facts, options.grid);
    facts.set(ReplanFacts::algorithm, std::string(to_string(algorithm)));
    facts.set(ReplanFacts::sensor_cells, options.sensor);  // 0: the whole raster
    facts.set(ReplanFacts::known_map, options.known_map);
  }
};

template <class Space>
BasicReplanningPlanner<Space>::BasicReplanningPlanner(const typename Space::Problem& world, ReplanAlgorithm algorithm,
                                                      ReplanningOptions options)
    : impl_(std::make_unique<Impl>(world, algorithm, options)) {}

template <class Space>
BasicReplanningPlanner<Space>::~BasicReplanningPlanner() = default;

template <class Space>
PlanReport<ExactPoint> BasicReplanningPlanner<Space>::plan(const Query& query, const QueryOptions& options) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  const Raster& first = r.phases.front().raster;
  PlanReport<ExactPoint> report;
  r.record_start(report.facts);
  const auto finish = [&] {
    report.facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  const auto snapped = snap_query(*r.problem, first, query, report);
  if (!snapped) return finish();

  std::size_t lived = 1;  // the phases the drive has seen
  const ReplanResult drive =
      drive_through_unknown_map(grid_map(first, r.problem->world().source), point_of(first, snapped->first),
                                point_of(first, snapped->second), r.drive_options(lived, querying.seconds()));
  r.record_facts(drive, lived, report.facts);
  const auto& last = r.phases[lived - 1];
  if (options.record) {
    report.recording.cells = std::make_shared<const CellGrid>(raster_cell_grid(last.raster));
    record_world_at_end(last.owned, report.recording);
  }
  if (drive.found) r.return_drive(query, drive, lived, report);
  else Impl::report_stop(drive, last, report);
  return finish();
}

template <class Space>
PlannerEntry<Space> replanning_planner_entry(ReplanAlgorithm algorithm) {
  OptionTable<ReplanningOptions> table;
  table
      .add("resolution", &ReplanningOptions::resolution, "cells per side of the bounds (n x n cells)",
           in_range(1, static_cast<double>(max_cells_per_axis)))
      .add("sensor", &ReplanningOptions::sensor,
           "sensing radius in cells (at least 1.41421357), 0: the robot sees the whole raster", at_least(0))
      .add("max-moves", &ReplanningOptions::max_moves,
           "moves before the drive stops with status limit (0: 4 x the cells)", at_least(1))
      .add("time", &ReplanningOptions::time, "time limit per query, seconds", above(0));
  add_grid_conventions(
      table, [](auto& o) -> auto& { return o.grid; });
  table.add("known-map", &ReplanningOptions::known_map,
            "the robot starts knowing the raster as it is at the start (changes are still found by sensing)");
  static constexpr const char* how[] = {"D* Lite (Koenig & Likhachev), the start moving with the robot",
                                        "LPA*, re-keyed each time the robot has moved",
                                        "A* from scratch at every replan"};
  PlannerEntry<Space> entry = make_planner_entry<Space, ReplanningOptions>(
      replanning_planner_name(algorithm),
      std::string("a robot drives the raster while the world's \"changes\" happen, replanning with ") +
          how[static_cast<int>(algorithm)],
      std::move(table), [algorithm](const typename Space::Problem& world, const ReplanningOptions& o) {
        return std::make_unique<BasicReplanningPlanner<Space>>(world, algorithm, o);
      });
  entry.follows_world_changes = true;
  return entry;
}

template class BasicReplanningPlanner<TranslatingRobot>;
template class BasicReplanningPlanner<RoundRobot>;
template PlannerEntry<TranslatingRobot> replanning_planner_entry<TranslatingRobot>(ReplanAlgorithm);
template PlannerEntry<RoundRobot> replanning_planner_entry<RoundRobot>(ReplanAlgorithm);

}  // namespace polyplan
