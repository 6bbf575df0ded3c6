#pragma once
// A robot that discovers its map as it drives (Koenig & Likhachev's setting for D* Lite): on a
// MovingAI grid it knows nothing at first but its own cell, assumes every unknown cell free, and at
// every cell it stands on senses each cell whose centre lies within Euclidean distance R of its own
// centre (or, with known_map, it starts knowing the map as it is at the start, and still learns of
// changes only by sensing). It moves on the grid of its conventions (by default 8-connected, steps
// 1 and √2, no corner cutting) along a shortest path on what it knows, and replans whenever what it
// knows changes. Between equally short moves it takes the neighbour nearest the goal in a straight
// line (then the first in the grid's order), so that drives are reproducible and comparable:
//
//   dstar_lite  D* Lite from the goal; the start moves with the robot (k_m)
//   lpastar     LPA* from the goal, its open list re-keyed each time the robot has moved
//   astar       a search from scratch each time (repeated A*, on the same graph, costs and heap)
//
// All three run on exact costs (OctileLength), so they plan the same costs: only the work differs.
// The robot stops at the goal, or as soon as the goal is unreachable on what it knows (no_path).
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/octile_length.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

enum class ReplanAlgorithm { dstar_lite, lpastar, astar };

// "dstar-lite", "lpastar", "astar": the command line's and the JSON's words.
std::string_view to_string(ReplanAlgorithm);
std::optional<ReplanAlgorithm> replan_algorithm_from_string(std::string_view);
// Every algorithm with its word, in that order (an option's choices).
std::vector<std::pair<std::string, ReplanAlgorithm>> replan_algorithm_choices();
// The same, throwing InputError "`what`: unknown algorithm "NAME" (dstar-lite, lpastar, astar)".
ReplanAlgorithm parse_replan_algorithm(std::string_view name, const std::string& what);

struct GridPoint {
  int x = 0, y = 0;  // column, row
  friend bool operator==(const GridPoint&, const GridPoint&) = default;
};

enum class CellKnowledge : std::uint8_t { unknown, free, blocked };

// One pass of a replan's search, in cells, as the course's planning problem set works it by hand.
struct ReplanTracePass {
  struct Cell {
    GridPoint at;
    OctileLength g, rhs;
    std::string action;  // the open list's: "add", "readd" (its key changed), "remove", "" (none)
  };
  struct Open {
    GridPoint at;
    OctileLength g, rhs, key_first, key_second;
    std::string state;  // "over" (g > rhs) or "under" (g < rhs)
  };
  std::size_t replan = 0, pass = 0;  // replan counts from 1, pass from 1 within it
  GridPoint popped;
  OctileLength key_first, key_second, g_before, g_after, rhs;
  OctileLength h;                        // the popped cell's heuristic (without k_m)
  std::optional<GridPoint> backpointer;  // the neighbour its rhs reads, after the pass (none: the goal, or rhs ∞)
  std::string kind;                      // "over" (g := rhs), "under" (g := ∞), "stale key" (put back)
  std::vector<Cell> updated;             // the rhs values it recomputed, in order
  std::vector<Open> open;                // the open list after the pass, by key
};

// The g and rhs of every cell after a replan, row-major (index y · width + x): the course's tables
// whole, for a trace that asks for them (ReplanTrace::wants_tables).
struct ReplanTables {
  std::size_t replan = 0;
  std::vector<OctileLength> g, rhs;
};

class ReplanTrace {
 public:
  virtual ~ReplanTrace() = default;
  // Before a replan's first pass: where the robot is and how many cells its sensing changed.
  virtual void replan_begins(std::size_t replan, GridPoint at, std::size_t changed_cells) = 0;
  virtual void pass(const ReplanTracePass&) = 0;
  // After each replan, when wants_tables(): every cell's g and rhs (a pass per cell to collect, so
  // only asked for).
  virtual bool wants_tables() const { return false; }
  virtual void tables(const ReplanTables&) {}
};

// The drive's options; replan_option_table() (incremental/replan_options.hpp) reads the first four
// by name, for the command line and Python alike.
struct ReplanOptions {
  ReplanAlgorithm algorithm = ReplanAlgorithm::dstar_lite;
  double sensor_radius = 1.5;  // finite and >= 0 (InputError otherwise)
  std::size_t max_moves = 0;   // 0: 4 x the map's cells; then status limit
  // The drive's bounds: its tables (about 75 bytes a cell, all allocated at the start) may take
  // `memory_mb` (a map that needs more is refused up front, InputError), and it stops with status
  // limit after `time_limit` seconds (0: none).
  double memory_mb = 4096;
  double time_limit = 300;
  ReplanTrace* trace = nullptr;
  // Called before the robot senses, with the moves made so far: a world that changes as the robot
  // drives (the truth may change; the robot learns of it only where it senses). Returns whether it
  // changed the truth: a robot that sees the whole map senses again only then.
  std::function<bool(std::size_t moves, GridMap& truth)> world_changes;
  // The grid: connectivity, corner cutting, diagonal cost. With 4 neighbours or corner cutting a
  // sensor radius of 1 sees every cell a move touches, else it must be at least √2.
  GridConventions grid{};
  bool known_map = false;  // the robot starts knowing the truth as it is before any change
};

struct ReplanStep {
  GridPoint at;
  OctileLength cost_to_goal;      // planned from `at` on the knowledge at that moment (∞: no path)
  std::size_t expanded = 0;       // by the replan here (0 when nothing changed: the plan held)
  std::size_t changed_cells = 0;  // cells whose believed state the sensing here changed
  bool replanned = false;
};

inline constexpr std::size_t never_seen = static_cast<std::size_t>(-1);

struct ReplanResult {
  PlanStatus status = PlanStatus::no_path;  // solved, no_path or limit
  bool found = false;
  ReplanAlgorithm algorithm = ReplanAlgorithm::dstar_lite;
  std::vector<GridPoint> traversed;  // start first; the goal last when found
  OctileLength traversed_cost;
  std::size_t moves = 0, replans = 0;
  std::size_t expanded = 0, generated = 0, heap_operations = 0;  // over every replan
  // One per cell the robot planned from: traversed[i] for every i but the goal's.
  std::vector<ReplanStep> steps;
  int width = 0, height = 0;
  std::vector<CellKnowledge> knowledge;  // at the end, row-major
  std::vector<std::size_t> seen_after;   // the moves made when each cell was first sensed (never_seen)
  std::vector<GridPoint> last_plan;      // the last planned path, from where it was made
  GridMap truth;                         // the map at the end (it may have changed)
  double seconds = 0;                    // in replanning (changes and searches)
  bool timed_out = false;                // status limit by the time limit (not the move limit)
  GridConventions grid{};                // the options': costs are in its units (grid.in_cells, grid.text)
  bool known_map = false;                // the options'
};

// Throws InputError for a start or goal outside the map or on a blocked cell of the truth, a
// sensor radius that is not finite or too small for the grid (smallest_sensor_radius).
// The smallest sensor radius that sees every cell a move touches: 1 with 4 neighbours or corner
// cutting, √2 otherwise (a diagonal move brushes the two cells beside it).
double smallest_sensor_radius(const GridConventions& grid);

ReplanResult drive_through_unknown_map(GridMap truth, GridPoint start, GridPoint goal, const ReplanOptions& options);

}  // namespace polyplan
