#include <polyplan/search/grid_graph.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace polyplan {

// The lazy cells' states: a flat byte per cell while the grid is small (a 2-joint C-space), a hash
// map of the cells touched otherwise (memory proportional to what the search saw).
struct GridGraph::LazyCache {
  static constexpr std::uint64_t flat_limit = std::uint64_t{1} << 24;
  std::vector<CellState> flat;
  std::unordered_map<GridCell, bool> touched;

  explicit LazyCache(std::uint64_t cells) {
    if (cells <= flat_limit) flat.assign(cells, CellState::unknown);
  }
  CellState get(GridCell c) const {
    if (!flat.empty()) return flat[c];
    const auto it = touched.find(c);
    return it == touched.end() ? CellState::unknown : it->second ? CellState::free : CellState::blocked;
  }
  void set(GridCell c, bool free) {
    if (!flat.empty()) flat[c] = free ? CellState::free : CellState::blocked;
    else touched.emplace(c, free);
  }
};

namespace {

std::string axis_name(std::size_t i) { return "grid axis " + std::to_string(i); }

}  // namespace

GridGraph::GridGraph(std::vector<GridAxis> axes, Connectivity connectivity, StepCost step_cost)
    : axes_(std::move(axes)), dimensions_(axes_.size()), connectivity_(connectivity) {
  if (axes_.empty()) throw std::invalid_argument("GridGraph: no axes");
  if (dimensions_ > max_dimensions)
    throw std::invalid_argument("GridGraph: " + std::to_string(dimensions_) + " axes, at most " +
                                std::to_string(max_dimensions));
  // A full neighbourhood has 3^N - 1 directions; beyond 8 axes that is no longer a grid to search.
  if (connectivity_ == Connectivity::full && dimensions_ > 8)
    throw std::invalid_argument("GridGraph: the full neighbourhood is limited to 8 axes (3^N - 1 moves)");
  std::uint64_t count = 1;
  for (std::size_t i = 0; i < dimensions_; ++i) {
    const GridAxis& a = axes_[i];
    const std::int64_t least = a.kind == AxisKind::wrapping ? 3 : 1;
    if (a.cells < least || a.cells > std::numeric_limits<GridCoordinate>::max())
      throw std::invalid_argument(axis_name(i) + ": " + std::to_string(a.cells) + " cells (a " +
                                  (a.kind == AxisKind::wrapping ? "wrapping" : "bounded") + " axis needs at least " +
                                  std::to_string(least) + ")");
    if (!(a.step > 0) || !std::isfinite(a.step))
      throw std::invalid_argument(axis_name(i) + ": the step must be positive and finite");
    strides_[i] = static_cast<std::int64_t>(count);
    if (count > (std::uint64_t{1} << 63) / static_cast<std::uint64_t>(a.cells))
      throw std::invalid_argument("GridGraph: more than 2^63 cells");
    count *= static_cast<std::uint64_t>(a.cells);
  }
  cell_count_ = count;

  // Directions: every offset vector in {-1, 0, 1}^N with one non-zero entry (axis_aligned) or at
  // least one (full), axis-aligned ones first. Guards of a multi-axis move: its sub-moves.
  std::vector<std::vector<std::int32_t>> offsets;
  std::vector<std::int32_t> o(dimensions_, -1);
  for (;;) {
    const auto nonzero = std::count_if(o.begin(), o.end(), [](std::int32_t v) { return v != 0; });
    if (nonzero == 1 || (nonzero > 1 && connectivity_ == Connectivity::full)) offsets.push_back(o);
    std::size_t i = 0;
    while (i < dimensions_ && o[i] == 1) o[i++] = -1;
    if (i == dimensions_) break;
    ++o[i];
  }
  std::stable_sort(offsets.begin(), offsets.end(), [](const auto& a, const auto& b) {
    const auto nz = [](const auto& v) {
      return std::count_if(v.begin(), v.end(), [](std::int32_t x) { return x != 0; });
    };
    return nz(a) < nz(b);
  });
  const auto index_of = [&](const std::vector<std::int32_t>& v) {
    return static_cast<std::uint32_t>(std::find(offsets.begin(), offsets.end(), v) - offsets.begin());
  };
  for (const auto& off : offsets) {
    Direction d;
    double squares = 0, sum = 0;
    std::vector<std::uint32_t> axes_moved;
    for (std::size_t i = 0; i < dimensions_; ++i) {
      if (off[i] == 0) continue;
      d.moves.push_back({static_cast<std::uint32_t>(i), off[i]});
      axes_moved.push_back(static_cast<std::uint32_t>(i));
      squares += axes_[i].step * axes_[i].step;
      sum += axes_[i].step;
    }
    d.cost = step_cost == StepCost::euclidean ? std::sqrt(squares) : sum;
    d.delta = 0;
    for (const AxisOffset& m : d.moves) d.delta += m.offset * strides_[m.axis];
    // Proper non-empty subsets of the moved axes.
    const std::size_t k = axes_moved.size();
    for (std::uint32_t mask = 1; mask + 1 < (1u << k); ++mask) {
      std::vector<std::int32_t> sub(dimensions_, 0);
      for (std::size_t b = 0; b < k; ++b)
        if (mask & (1u << b)) sub[axes_moved[b]] = off[axes_moved[b]];
      d.guards.push_back(index_of(sub));
    }
    directions_.push_back(std::move(d));
  }
}

GridGraph::GridGraph(std::vector<GridAxis> axes, Connectivity connectivity, StepCost step_cost,
                     std::vector<std::uint8_t> free_cells)
    : GridGraph(std::move(axes), connectivity, step_cost) {
  if (free_cells.size() != cell_count_)
    throw std::invalid_argument("GridGraph: the bitmap has " + std::to_string(free_cells.size()) + " cells, the axes " +
                                std::to_string(cell_count_));
  bitmap_ = true;
  free_bitmap_ = std::move(free_cells);
}

GridGraph::GridGraph(std::vector<GridAxis> axes, Connectivity connectivity, StepCost step_cost, CellTest is_free)
    : GridGraph(std::move(axes), connectivity, step_cost) {
  if (!is_free) throw std::invalid_argument("GridGraph: empty cell test");
  cell_test_ = std::move(is_free);
  cache_ = std::make_unique<LazyCache>(cell_count_);
}

GridGraph::~GridGraph() = default;
GridGraph::GridGraph(GridGraph&&) noexcept = default;
GridGraph& GridGraph::operator=(GridGraph&&) noexcept = default;

void GridGraph::set_move_test(MoveTest test) { move_test_ = std::move(test); }

GridCell GridGraph::cell(std::span<const GridCoordinate> at) const {
  if (at.size() != dimensions_)
    throw std::out_of_range("GridGraph::cell: " + std::to_string(at.size()) + " coordinates for " +
                            std::to_string(dimensions_) + " axes");
  GridCell c = 0;
  for (std::size_t i = 0; i < dimensions_; ++i) {
    if (at[i] < 0 || at[i] >= axes_[i].cells)
      throw std::out_of_range("GridGraph::cell: coordinate " + std::to_string(at[i]) + " outside " + axis_name(i) +
                              " [0, " + std::to_string(axes_[i].cells) + ")");
    c += static_cast<GridCell>(at[i]) * static_cast<GridCell>(strides_[i]);
  }
  return c;
}

void GridGraph::coordinates(GridCell c, std::span<GridCoordinate> out) const {
  for (std::size_t i = 0; i < dimensions_; ++i) {
    const auto n = static_cast<GridCell>(axes_[i].cells);
    out[i] = static_cast<GridCoordinate>(c % n);
    c /= n;
  }
}

std::vector<GridCoordinate> GridGraph::coordinates(GridCell c) const {
  std::vector<GridCoordinate> out(dimensions_);
  coordinates(c, out);
  return out;
}

bool GridGraph::lazy_is_free(GridCell c) const {
  switch (cache_->get(c)) {
    case CellState::free: return true;
    case CellState::blocked: return false;
    case CellState::unknown: break;
  }
  Coordinates at;
  coordinates(c, at);
  const bool free = cell_test_(std::span<const GridCoordinate>(at.data(), dimensions_));
  ++cells_evaluated_;
  cache_->set(c, free);
  return free;
}

GridGraph::CellState GridGraph::state(GridCell c) const {
  if (bitmap_) return free_bitmap_[c] ? CellState::free : CellState::blocked;
  return cache_->get(c);
}

void GridGraph::evaluate_all() const {
  if (bitmap_) return;
  if (cell_count_ > LazyCache::flat_limit)
    throw std::invalid_argument("GridGraph::evaluate_all: " + std::to_string(cell_count_) +
                                " cells is too many to evaluate eagerly");
  for (GridCell c = 0; c < cell_count_; ++c) lazy_is_free(c);
}

bool GridGraph::checked_move(GridCell from, GridCell to) const {
  ++moves_checked_;
  return move_test_(from, to);
}

GridDistanceTo::GridDistanceTo(const GridGraph& graph, GridCell goal, GridMetric metric)
    : graph_(&graph), metric_(metric) {
  if (metric == GridMetric::octile && graph.dimensions() != 2)
    throw std::invalid_argument("GridDistanceTo: the octile metric needs a 2D grid, this one has " +
                                std::to_string(graph.dimensions()) + " axes");
  // With unequal steps max + (sqrt 2 - 1) min overestimates the diagonal: not a heuristic A* may use.
  if (metric == GridMetric::octile && graph.axis(0).step != graph.axis(1).step)
    throw std::invalid_argument("GridDistanceTo: the octile metric needs square cells (equal axis steps)");
  if (const auto cost = graph.diagonal_cost()) diagonal_extra_ = *cost - 1;
  const auto at = graph.coordinates(goal);
  std::copy(at.begin(), at.end(), goal_.begin());
  plane_octile_ = metric == GridMetric::octile && graph.axis(0).kind == AxisKind::bounded &&
                  graph.axis(1).kind == AxisKind::bounded;
  if (plane_octile_) {
    width_ = static_cast<GridCell>(graph.axis(0).cells);
    step_ = {graph.axis(0).step, graph.axis(1).step};
  }
}

void GridGraph::set_diagonals(std::optional<double> cost, bool corner_cutting) {
  if (dimensions_ != 2) throw std::invalid_argument("GridGraph: diagonal conventions are for 2D grids");
  if (cost && axes_[0].step != axes_[1].step)
    throw std::invalid_argument("GridGraph: a diagonal cost needs square cells (equal axis steps)");
  diagonal_cost_ = cost;
  for (Direction& d : directions_) {
    if (d.moves.size() != 2) continue;
    if (cost) d.cost = *cost * axes_[0].step;  // else the Euclidean length the constructor gave it
    if (corner_cutting) d.guards.clear();
  }
}

double GridDistanceTo::general(GridCell c) const {
  std::array<GridCoordinate, GridGraph::max_dimensions> at;
  graph_->coordinates(c, at);
  std::array<double, GridGraph::max_dimensions> d;
  const std::size_t n = graph_->dimensions();
  for (std::size_t i = 0; i < n; ++i) {
    const GridAxis& a = graph_->axis(i);
    std::int64_t cells = std::abs(std::int64_t{at[i]} - goal_[i]);
    if (a.kind == AxisKind::wrapping) cells = std::min(cells, a.cells - cells);
    d[i] = static_cast<double>(cells) * a.step;
  }
  switch (metric_) {
    case GridMetric::octile: {
      const auto [lo, hi] = std::minmax(d[0], d[1]);
      return hi + diagonal_extra_ * lo;
    }
    case GridMetric::euclidean: {
      double s = 0;
      for (std::size_t i = 0; i < n; ++i) s += d[i] * d[i];
      return std::sqrt(s);
    }
    case GridMetric::sum_of_axes: {
      double s = 0;
      for (std::size_t i = 0; i < n; ++i) s += d[i];
      return s;
    }
  }
  return 0;
}

}  // namespace polyplan
