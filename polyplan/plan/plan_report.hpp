#pragma once
// What every planner answers for one query, whatever it plans over (a point in a polygon world,
// a pose, the joint angles of an arm): its status, found or why not, the path and its length, how the
// path was proved free, and the planner's facts, typed (plan/fact_key.hpp). One JSON writer
// (plan/plan_json.hpp) prints any report and one draw_plan (draw/plan_svg.hpp) draws it,
// neither knowing which planner made it.
#include <polyplan/plan/fact_key.hpp>
#include <polyplan/plan/plan_facts.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace polyplan {

class CSpace;  // geometry/cspace.hpp

// A point of the plane as a fact: (x, y), where a walk stopped.
using FactPoint = std::array<double, 2>;
// Points in order: a walk's hit points, a tether's polyline.
using FactPoints = std::vector<FactPoint>;
// A grid cell as a fact: (column, row).
using FactCell = std::array<std::int64_t, 2>;

// A fact's value: a flag, a count, a measure, a word, or a point, points or a cell (JSON: arrays
// of numbers, never text, so that a reader gets numbers back).
using FactValue = std::variant<bool, std::int64_t, double, std::string, FactPoint, FactPoints, FactCell>;

// The facts a planner reports beside its path, set and read through the keys its family declares
// (plan/fact_key.hpp; the shared ones, search.expanded, roadmap.vertices, query_seconds,
// stopped_by, note, ..., in plan/plan_facts.hpp). They keep the order in which they were first
// set. A `note` is a remark on the answer that the command line prints after its summary line.
class Facts {
 public:
  // Sets a fact, replacing an earlier value: a flag from a bool, a count from any integer, a
  // measure from any number, a word from text, a point, points or a cell from its own type.
  template <class T, class V>
  void set(FactKey<T> key, const V& value) {
    put(key.name, FactValue(converted<T>(value)));
  }

  // The fact's value; std::out_of_range naming it when the report has none.
  template <class T>
  const T& at(FactKey<T> key) const {
    const FactValue* value = value_named(key.name);
    if (!value) throw std::out_of_range("no fact \"" + std::string(key.name) + "\"");
    return std::get<T>(*value);
  }
  // The same, or none.
  template <class T>
  std::optional<T> find(FactKey<T> key) const {
    const FactValue* value = value_named(key.name);
    return value ? std::optional<T>(std::get<T>(*value)) : std::nullopt;
  }
  template <class T>
  bool contains(FactKey<T> key) const {
    return value_named(key.name) != nullptr;
  }

  // Every fact in the order first set, for the writers that list them all (the JSON, a CSV's
  // columns), and one by the name such a listing gave.
  const std::vector<std::pair<std::string, FactValue>>& entries() const { return entries_; }
  const FactValue* value_named(std::string_view name) const;

 private:
  template <class T, class V>
  static T converted(const V& value) {
    constexpr bool number = std::is_arithmetic_v<V> && !std::is_same_v<V, bool>;
    if constexpr (std::is_same_v<T, bool>) {
      static_assert(std::is_same_v<V, bool>, "a flag is set from a bool");
      return value;
    } else if constexpr (std::is_same_v<T, std::int64_t>) {
      static_assert(number && std::is_integral_v<V>, "a count is set from an integer");
      return static_cast<std::int64_t>(value);
    } else if constexpr (std::is_same_v<T, double>) {
      static_assert(number, "a measure is set from a number");
      return static_cast<double>(value);
    } else if constexpr (std::is_same_v<T, std::string>) {
      static_assert(std::is_convertible_v<const V&, std::string_view>, "a word is set from text");
      return std::string(std::string_view(value));
    } else {
      static_assert(std::is_same_v<V, T>, "a point, points or a cell is set from its own type");
      return value;
    }
  }

  void put(std::string_view name, FactValue value);
  std::vector<std::pair<std::string, FactValue>> entries_;
};

// How a returned path was proved free for every configuration along it (docs/design.md: motions are
// certified, never sampled). Every polyplan planner certifies what it returns.
struct Certificate {
  bool certified = false;
  std::string method;  // e.g. "exact path check (triangulation walk)", "conservative advancement"
};

// A roadmap or a search tree as a picture shows it: configurations, and the pairs joined by a
// motion of the planner.
template <class Configuration>
struct PlanGraph {
  std::string kind;  // the legend's word: "roadmap" or "tree"
  std::vector<Configuration> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  // Optional, one per edge: the control point of the quadratic Bézier curve the edge follows (a
  // Voronoi diagram's parabolic arc); none for a straight edge, and empty when every edge is.
  std::vector<std::optional<Configuration>> bends;
  // Optional, one per edge: what the edge is to the obstacles it touches — a visibility graph's
  // "supporting" bitangent (both obstacles on one side of it), "separating" (on either side), or
  // "other" (not tangent at an end); empty for graphs that do not say.
  std::vector<std::string> edge_kinds;
};

// Cells over two coordinates of the configuration (x and y, or θ1 and θ2) and what the planner
// knows of them: a raster's occupancy, the part of an arm's C-space grid a lazy search evaluated,
// a distance field over the free cells and its ridge (the grid GVD).
struct CellGrid {
  // ridge: a free cell on a line the planner travels along (the GVD of gvd-grid).
  enum State : std::uint8_t { not_evaluated = 0, free = 1, blocked = 2, ridge = 3 };
  std::size_t columns = 0, rows = 0;
  double x0 = 0, y0 = 0;  // the lower-left corner of cell (0, 0)
  double cell_width = 1, cell_height = 1;
  std::vector<std::uint8_t> states;  // columns · rows States, index column + row · columns
  // Optional: a value per cell (as many as states, same index), drawn as a heat map over the free
  // and ridge cells, e.g. the distance to the nearest obstacle; empty when the planner has none. `value_name`
  // says what it is, for the legend.
  std::vector<float> values;
  std::string value_name;
  bool wraps = false;  // opposite edges meet (the torus of an arm's two joint angles)
  State state(std::size_t column, std::size_t row) const { return static_cast<State>(states[column + row * columns]); }
};

// A decomposition of the free space into convex cells as a picture shows it: each cell's corners
// in order, and the walls through which the planner passes from one cell into the next.
template <class Configuration>
struct PlanDecomposition {
  std::string kind;  // the legend's word: "trapezoids"
  std::vector<std::vector<Configuration>> cells;
  std::vector<std::pair<Configuration, Configuration>> walls;
};

// What a planner marks on the picture beyond the path, under a legend word of its own: a reactive
// planner's hit and leave points, its m-line, its sensor's regions, the walk of a robot that
// stopped before the goal. Drawn by kind (points as rings, lines dashed, regions tinted), so that a
// planner needs no drawing code to show them.
template <class Configuration>
struct PlanMark {
  enum class Kind : std::uint8_t { points, lines, regions };
  Kind kind;
  std::string legend;
  // points: one part, the points; lines: each part a polyline; regions: each part a ring.
  std::vector<std::vector<Configuration>> parts;
};

// One of several answers a planner gives to one query (the shortest path of each of K homotopy
// classes): its path, its length and its own facts (its class's word). JSON: "paths", each
// {found, length, path, path_exact, facts...}; the picture draws each.
template <class Configuration>
struct PlanPath {
  std::vector<Configuration> path;
  double length = 0;
  Facts facts;
  std::string label;  // what the picture's legend calls it beside its number (a class's word)
};

// What became of a query, for a caller to branch on (OMPL's PlannerStatus is the model). Every
// status but `solved` comes with a sentence in PlanReport::why_not.
enum class PlanStatus : std::uint8_t {
  solved,         // found: the path is certified free
  no_path,        // proved: no path exists (the planner is complete for this query: an exact
                  // roadmap without a path, start and goal in different components of the free space)
  not_found,      // none found by a planner that is not complete here (a grid at its resolution, a
                  // diagram rounded shut, a join that failed): a path may still exist
  limit,          // a time, iteration or memory limit ended the search; the fact stopped_by says which
  invalid_query,  // the start or the goal is not free, or lies outside the world
  local_minimum,  // a reactive planner stopped where no move improves
};

// Every status, in the enumeration's order.
inline constexpr std::array<PlanStatus, 6> all_plan_statuses{PlanStatus::solved,        PlanStatus::no_path,
                                                             PlanStatus::not_found,     PlanStatus::limit,
                                                             PlanStatus::invalid_query, PlanStatus::local_minimum};

// "solved", "no_path", ...: the JSON's and the command line's word.
std::string_view to_string(PlanStatus status);

// How two consecutive points of a path join when not by a straight motion alone: a disc robot's
// shortest path runs along arcs of circles between its tangents (roadmaps/tangent_visibility.hpp).
// In doubles: the points where tangents touch circles are irrational (the planner decided them
// exactly). JSON: "pieces", each {kind, from, to, length, and for an arc centre, radius, turn}.
struct PathPiece {
  enum class Kind : std::uint8_t { segment, arc };
  Kind kind = Kind::segment;
  FactPoint from{}, to{};
  FactPoint centre{};             // an arc's
  double radius = 0;              // an arc's
  bool counter_clockwise = true;  // an arc's turn
  double length = 0;
};

// The narrowest place of a found path, for the planners that maximise clearance: where it is and
// its distance to the nearest obstacle. JSON: clearance, bottleneck {x, y}; the picture draws the disc.
struct Bottleneck {
  double x = 0, y = 0;
  double clearance = 0;
};

// One expansion of a planner's graph search (search/search_trace.hpp's ExpansionRecord) with where
// its vertex is: for watching the search. `vertex` and `backpointer` are indices in the graph the
// planner searched (its roadmap with the query's start and goal joined to it).
template <class Configuration>
struct PlanExpansion {
  std::size_t step = 0;  // from 1
  std::size_t vertex = 0;
  Configuration at{};
  double g = 0, h = 0, f = 0;
  std::optional<std::size_t> backpointer;
  std::size_t open = 0;
};

// A solution's length when the planner had it: an anytime planner's progress (the first solution,
// then each better one), read by cost-over-time curves (`polyplan benchmark`).
struct SolutionImprovement {
  double seconds = 0;  // on the query's clock
  double length = 0;   // in the planner's metric, as PlanReport::length
};

// What a picture shows of how a planner answered, apart from the answer a caller branches on
// (PlanReport): kept when the query asks for it (QueryOptions::record, QueryOptions::trace), empty
// otherwise. The graph, the cells and the decomposition are the planner's, shared by the reports of
// its queries.
template <class Configuration>
struct PlanRecording {
  std::shared_ptr<const PlanGraph<Configuration>> graph;
  std::vector<Configuration> expanded;  // where the search expanded, in order
  // Every expansion of the graph search (QueryOptions::trace), by the planners that search a graph
  // with search/'s shortest_path; empty for the others.
  std::vector<PlanExpansion<Configuration>> trace;
  std::shared_ptr<const CellGrid> cells;
  std::shared_ptr<const PlanDecomposition<Configuration>> decomposition;
  // The C-space of the world the answer ends in, when the world changed on the way (a world
  // file's "changes"): the picture draws it instead of the problem's. Null: the problem's.
  std::shared_ptr<const CSpace> world_at_end;
  std::vector<PlanMark<Configuration>> marks;
};

template <class Configuration>
struct PlanReport {
  bool found = false;
  PlanStatus status = PlanStatus::not_found;  // solved exactly when found
  // When not found: one sentence saying what stopped the planner ("the start [3, 4] is not free:
  // it is inside obstacles[2]", "start and goal lie in different components of the free space").
  std::string why_not;
  // When found: the query's start exactly, ..., the query's goal exactly. When a reactive planner
  // stopped short of the goal (local_minimum, limit): the walk from the start to where it stopped,
  // every motion of it proved free as a found path's is, so that a caller can show where the robot
  // got stuck. Empty otherwise.
  std::vector<Configuration> path;
  // In the planner's metric: Euclidean for points, the sum of the joints' turns for arms. A
  // double: irrational by nature.
  double length = 0;
  Certificate certificate;
  std::optional<Bottleneck> bottleneck;
  Facts facts;
  // Each better solution as the planner found it, in order, the last one `length` (the sampling
  // planners: the first path, RRT*'s improvements, the shortcut path); empty for a planner that
  // answers once, when its whole query is its one solution.
  std::vector<SolutionImprovement> improvements;

  // When not empty, pieces[k] joins path[k] to path[k + 1] (a segment or an arc); path[0] and the
  // last point are then the query's start and goal exactly, the points between them the nearest
  // doubles of irrational points. Empty: the path is the polyline through `path`.
  std::vector<PathPiece> pieces;

  // Several answers, for a planner that gives several: paths[0] is `path`; empty for the others.
  std::vector<PlanPath<Configuration>> paths;

  // What only a picture needs, apart from the answer: empty unless the query asks for it.
  PlanRecording<Configuration> recording;

  // An answer without a path: why, as a status and as a sentence.
  void fail(PlanStatus failure, std::string why) {
    found = false;
    status = failure;
    why_not = std::move(why);
  }
  // A certified path is in `path`.
  void succeed() {
    found = true;
    status = PlanStatus::solved;
  }
};

}  // namespace polyplan
