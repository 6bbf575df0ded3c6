#pragma once
// An implicit N-dimensional grid of cells as a Boost Graph IncidenceGraph, searched with the same
// shortest_path as every roadmap (search/graph_search.hpp): MovingAI maps (2D, 8-connected), the
// rasterised polygon worlds of the course's graph-search homework, and the torus-shaped C-space of an n-link arm.
//
// Nothing of the grid is stored but what it is given or what a search touched:
// - axes are bounded ([0, n)) or wrapping (a circle: cell n-1 neighbours cell 0, e.g. a joint angle);
// - moves go along one axis (axis_aligned: 4-connected in 2D) or along any combination of axes
//   (full: 8-connected in 2D). A move along several axes never cuts a corner: every cell it would
//   brush (each sub-move) must be free too, the MovingAI rule;
// - a cell is free or blocked by a bitmap, or by a test called the first time a search touches it
//   and cached: memory proportional to the cells touched (a hash map once the grid is too big for
//   a flat cache), so a 7-joint arm at 5 degrees (72^7 = 10^13 cells) still plans.
// - an optional move test rejects moves between free cells (an arm's motion checked finely).
//
// The hot path (out_edges, is_free on a bitmap) is inline here: it is what A* spends its time in.
// Not thread-safe: the lazy cache and the counters change while a search runs (one graph per thread).
#include <polyplan/search/search_result.hpp>
#include <polyplan/search/search_workspace.hpp>

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/iterator_facade.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace polyplan {

using GridCell = std::uint64_t;       // linear index; axis 0 varies fastest
using GridCoordinate = std::int32_t;  // a cell's index along one axis

enum class AxisKind { bounded, wrapping };

struct GridAxis {
  std::int64_t cells = 0;  // >= 1 (>= 3 when wrapping, so that the two neighbours differ)
  AxisKind kind = AxisKind::bounded;
  double step = 1.0;  // the length of one cell along this axis (> 0), for costs and heuristics
};

enum class Connectivity {
  axis_aligned,  // change one coordinate by one: 4-connected in 2D, 2N neighbours
  full,          // change any coordinates by one: 8-connected in 2D, 3^N - 1 neighbours, no corner cutting
};

enum class StepCost {
  euclidean,    // sqrt(sum (d_i step_i)^2): 1 and sqrt(2) on a unit 2D grid (MovingAI's octile lengths)
  sum_of_axes,  // sum |d_i| step_i: an arm path's length as the sum of its joints' rotations
};

// An edge: a move from source to target in one of the graph's directions.
struct GridMove {
  GridCell source = 0, target = 0;
  std::uint32_t direction = 0;
  friend bool operator==(const GridMove&, const GridMove&) = default;
};

class GridGraph;
class GridMoveIterator;

std::pair<GridMoveIterator, GridMoveIterator> out_edges(GridCell, const GridGraph&);

class GridGraph {
 public:
  static constexpr std::size_t max_dimensions = 12;
  using CellTest = std::function<bool(std::span<const GridCoordinate>)>;  // true: the cell is free
  using MoveTest = std::function<bool(GridCell from, GridCell to)>;       // true: the move is allowed

  // Cells given by a bitmap: free_cells[cell] != 0 means free (size: cell_count()).
  GridGraph(std::vector<GridAxis> axes, Connectivity, StepCost, std::vector<std::uint8_t> free_cells);
  // Cells decided by `is_free`, called at most once per cell, when a search first needs it.
  GridGraph(std::vector<GridAxis> axes, Connectivity, StepCost, CellTest is_free);
  // Throws std::invalid_argument for no axes, more than max_dimensions, an axis with too few
  // cells or a step that is not positive, more than 2^63 cells, or a bitmap of the wrong size.
  ~GridGraph();
  GridGraph(GridGraph&&) noexcept;
  GridGraph& operator=(GridGraph&&) noexcept;

  // Moves between free neighbours must also pass `test` (checked each time a search looks at the
  // move, counted in moves_checked). An empty function removes the test.
  void set_move_test(MoveTest test);

  // A 2D grid's diagonal moves (search/grid_conventions.hpp): their cost in steps of the axes
  // (nullopt: the Euclidean length, √2 steps) and whether one may pass a blocked cell's corner.
  // Throws std::invalid_argument for a grid that is not 2D, or a cost on cells that are not square.
  void set_diagonals(std::optional<double> cost, bool corner_cutting);
  std::optional<double> diagonal_cost() const { return diagonal_cost_; }

  std::size_t dimensions() const { return dimensions_; }
  const GridAxis& axis(std::size_t i) const { return axes_[i]; }
  std::uint64_t cell_count() const { return cell_count_; }
  Connectivity connectivity() const { return connectivity_; }

  // Throws std::out_of_range for a coordinate outside its axis or a wrong number of coordinates.
  GridCell cell(std::span<const GridCoordinate> coordinates) const;
  GridCell cell(std::initializer_list<GridCoordinate> coordinates) const {
    return cell(std::span<const GridCoordinate>(coordinates.begin(), coordinates.size()));
  }
  void coordinates(GridCell, std::span<GridCoordinate> out) const;  // out.size() >= dimensions()
  std::vector<GridCoordinate> coordinates(GridCell c) const;

  // Evaluates the cell if the test has not seen it yet.
  bool is_free(GridCell c) const {
    if (bitmap_) return free_bitmap_[c] != 0;
    return lazy_is_free(c);
  }
  enum class CellState : std::uint8_t { unknown, free, blocked };
  CellState state(GridCell) const;  // without evaluating
  // Evaluates every cell now (eager evaluation; for small grids, e.g. to draw a 2-joint C-space).
  void evaluate_all() const;

  // Calls of the cell test so far (each cell at most once), and of the move test.
  std::size_t cells_evaluated() const { return cells_evaluated_; }
  std::size_t moves_checked() const { return moves_checked_; }

  double move_cost(const GridMove& m) const { return directions_[m.direction].cost; }
  std::size_t direction_count() const { return directions_.size(); }

 private:
  friend class GridMoveIterator;
  friend std::pair<GridMoveIterator, GridMoveIterator> out_edges(GridCell, const GridGraph&);

  struct AxisOffset {
    std::uint32_t axis;
    std::int32_t offset;  // -1 or +1
  };
  struct Direction {
    std::vector<AxisOffset> moves;      // the axes it changes
    std::vector<std::uint32_t> guards;  // directions of its proper sub-moves: cells that must be free too
    double cost;
    std::int64_t delta;  // the change of the linear index when no axis wraps or ends
  };
  using Coordinates = std::array<GridCoordinate, max_dimensions>;

  GridGraph(std::vector<GridAxis> axes, Connectivity, StepCost);
  bool lazy_is_free(GridCell) const;
  bool checked_move(GridCell from, GridCell to) const;

  // Coordinates of a cell; in 2D with one division (the generic loop takes two), since A* decodes
  // every cell it expands.
  void decode(GridCell c, Coordinates& at) const {
    if (dimensions_ == 2) {
      const auto width = static_cast<GridCell>(axes_[0].cells);
      const GridCell y = c / width;
      at[0] = static_cast<GridCoordinate>(c - y * width);
      at[1] = static_cast<GridCoordinate>(y);
      return;
    }
    coordinates(c, std::span<GridCoordinate>(at.data(), dimensions_));
  }
  // Whether no move out of `at` leaves or wraps an axis: then every neighbour is at a fixed index
  // offset (Direction::delta). Most cells of a big grid are interior.
  bool interior(const Coordinates& at) const {
    for (std::size_t i = 0; i < dimensions_; ++i)
      if (at[i] == 0 || at[i] + 1 >= axes_[i].cells) return false;
    return true;
  }
  // The neighbour of `from` (at `at`) in direction d, false when it leaves a bounded axis.
  bool neighbour(GridCell from, const Coordinates& at, std::uint32_t d, GridCell& to) const {
    std::int64_t delta = 0;
    for (const AxisOffset& m : directions_[d].moves) {
      const std::int64_t c = std::int64_t{at[m.axis]} + m.offset, n = axes_[m.axis].cells;
      if (c >= 0 && c < n) {
        delta += m.offset * strides_[m.axis];
      } else {
        if (axes_[m.axis].kind == AxisKind::bounded) return false;
        delta += (c < 0 ? n - 1 : 1 - n) * strides_[m.axis];  // across the seam
      }
    }
    to = from + static_cast<GridCell>(delta);
    return true;
  }
  // The same cells are tested in the same order on both paths (a lazy test sees no difference).
  bool allows(GridCell from, const Coordinates& at, bool inside, std::uint32_t d, GridCell& to) const {
    const Direction& direction = directions_[d];
    if (inside) {
      to = from + static_cast<GridCell>(direction.delta);
      if (!is_free(to)) return false;
      for (const std::uint32_t g : direction.guards)
        if (!is_free(from + static_cast<GridCell>(directions_[g].delta))) return false;
    } else {
      if (!neighbour(from, at, d, to) || !is_free(to)) return false;
      for (const std::uint32_t g : direction.guards) {
        GridCell brushed;
        if (!neighbour(from, at, g, brushed) || !is_free(brushed)) return false;
      }
    }
    return !move_test_ || checked_move(from, to);
  }

  std::vector<GridAxis> axes_;
  std::size_t dimensions_ = 0;
  std::array<std::int64_t, max_dimensions> strides_{};
  std::uint64_t cell_count_ = 0;
  Connectivity connectivity_;
  std::vector<Direction> directions_;
  bool bitmap_ = false;
  std::vector<std::uint8_t> free_bitmap_;
  CellTest cell_test_;
  MoveTest move_test_;
  std::optional<double> diagonal_cost_;
  struct LazyCache;
  std::unique_ptr<LazyCache> cache_;
  mutable std::size_t cells_evaluated_ = 0, moves_checked_ = 0;
};

// Iterates over the allowed moves out of one cell (boost::graph_traits<GridGraph>::out_edge_iterator).
class GridMoveIterator
    : public boost::iterator_facade<GridMoveIterator, GridMove, std::forward_iterator_tag, GridMove> {
 public:
  GridMoveIterator() = default;

 private:
  friend class boost::iterator_core_access;
  friend std::pair<GridMoveIterator, GridMoveIterator> out_edges(GridCell, const GridGraph&);

  void skip_disallowed() {
    const auto end = static_cast<std::uint32_t>(graph_->directions_.size());
    while (direction_ < end && !graph_->allows(source_, at_, interior_, direction_, target_)) ++direction_;
  }
  GridMove dereference() const { return {source_, target_, direction_}; }
  void increment() {
    ++direction_;
    skip_disallowed();
  }
  bool equal(const GridMoveIterator& other) const { return direction_ == other.direction_; }

  const GridGraph* graph_ = nullptr;
  GridCell source_ = 0, target_ = 0;
  std::uint32_t direction_ = 0;
  bool interior_ = false;
  GridGraph::Coordinates at_{};
};

inline std::pair<GridMoveIterator, GridMoveIterator> out_edges(GridCell c, const GridGraph& g) {
  GridMoveIterator first, last;
  first.graph_ = last.graph_ = &g;
  first.source_ = last.source_ = c;
  g.decode(c, first.at_);
  first.interior_ = g.interior(first.at_);
  last.direction_ = static_cast<std::uint32_t>(g.directions_.size());
  first.skip_disallowed();
  return {first, last};
}
inline std::size_t out_degree(GridCell c, const GridGraph& g) {
  std::size_t n = 0;
  for (auto [e, end] = out_edges(c, g); e != end; ++e) ++n;
  return n;
}
inline GridCell source(const GridMove& m, const GridGraph&) { return m.source; }
inline GridCell target(const GridMove& m, const GridGraph&) { return m.target; }
inline std::uint64_t num_vertices(const GridGraph& g) { return g.cell_count(); }

// Cells are the integers 0..cell_count()-1, so a search workspace may keep a flat table of
// cell_count() records, but only while that is small (8M cells: a 2900 x 2900 map); beyond, it
// hashes the cells touched.
template <>
struct has_dense_vertex_ids<GridGraph> : std::true_type {};
inline bool dense_vertex_table_fits(const GridGraph& g) { return g.cell_count() <= (std::uint64_t{1} << 23); }

// The edge weight function for shortest_path.
struct GridMoveCost {
  const GridGraph* graph;
  double operator()(const GridMove& m) const { return graph->move_cost(m); }
};

enum class GridMetric {
  octile,       // 2D, square cells only: max + (sqrt 2 - 1) min; exact on an empty 8-connected grid
  euclidean,    // sqrt of the sum of squared axis distances
  sum_of_axes,  // the sum of the axis distances (on wrapping angle axes: the total angular distance)
};

// A heuristic for shortest_path: the distance from a cell to the goal, each axis distance the
// shorter way round on a wrapping axis (on a 72-cell angle axis, cells 71 and 1 are 2 apart), in
// the axes' step units. Admissible when the metric never exceeds the move costs: octile or
// euclidean with StepCost::euclidean, any of them with StepCost::sum_of_axes.
class GridDistanceTo {
 public:
  // Throws std::invalid_argument for octile on a grid that is not 2D or whose cells are not square.
  // Octile follows the graph's diagonal cost: max + (cost - 1) min (for a cost of 2 or more use
  // sum_of_axes: two straight moves are then never dearer).
  GridDistanceTo(const GridGraph& graph, GridCell goal, GridMetric metric);
  double operator()(GridCell c) const {
    if (!plane_octile_) return general(c);
    // A* calls this for every cell it reaches: the octile distance on a bounded 2D grid, inline.
    const GridCell y = c / width_;
    const double dx = static_cast<double>(std::abs(static_cast<std::int64_t>(c - y * width_) - goal_[0])) * step_[0];
    const double dy = static_cast<double>(std::abs(static_cast<std::int64_t>(y) - goal_[1])) * step_[1];
    return dx < dy ? dy + (diagonal_extra_ * dx) : dx + (diagonal_extra_ * dy);
  }

 private:
  // std::sqrt(2.0) - 1.0 to the last bit (the diagonal move costs std::sqrt(2.0)), as a constant.
  static constexpr double sqrt2_minus_1 = 0x1.a827999fcef34p-2;
  double general(GridCell c) const;

  const GridGraph* graph_;
  std::array<std::int64_t, GridGraph::max_dimensions> goal_{};
  GridMetric metric_;
  double diagonal_extra_ = sqrt2_minus_1;  // a diagonal's cost beyond a straight move's, in steps
  bool plane_octile_ = false;              // octile on two bounded axes: the inline case
  GridCell width_ = 1;
  std::array<double, 2> step_{};
};

}  // namespace polyplan

namespace boost {
template <>
struct graph_traits<polyplan::GridGraph> {
  using vertex_descriptor = polyplan::GridCell;
  using edge_descriptor = polyplan::GridMove;
  using out_edge_iterator = polyplan::GridMoveIterator;
  using directed_category = directed_tag;  // every move has its reverse; BGL need not know
  using edge_parallel_category = disallow_parallel_edge_tag;
  using traversal_category = incidence_graph_tag;
  using degree_size_type = std::size_t;
  using vertices_size_type = std::uint64_t;
  static vertex_descriptor null_vertex() { return ~polyplan::GridCell{0}; }
};
}  // namespace boost
