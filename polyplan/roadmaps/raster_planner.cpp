#include <polyplan/roadmaps/raster_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/search/graph_search.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

Rational cell_width(const Raster& r) { return (r.bounds.xmax - r.bounds.xmin) / Rational(mpz_class(r.cells_per_axis)); }
Rational cell_height(const Raster& r) { return (r.bounds.ymax - r.bounds.ymin) / Rational(mpz_class(r.cells_per_axis)); }

// Steps in world units, so that search costs are lengths (a non-square cell's diagonal included).
std::vector<GridAxis> axes_of(const Raster& r) {
  const auto n = static_cast<std::int64_t>(r.cells_per_axis);
  return {{n, AxisKind::bounded, to_double(cell_width(r))}, {n, AxisKind::bounded, to_double(cell_height(r))}};
}

std::vector<std::uint8_t> free_cells_of(const Raster& r) {
  std::vector<std::uint8_t> free(r.blocked.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = r.blocked[i] ? 0 : 1;
  return free;
}

const Raster& checked_against(const Raster& raster, const CSpace& cspace) {
  const auto& b = cspace.world().bounds;
  if (!b || b->xmin != raster.bounds.xmin || b->ymin != raster.bounds.ymin || b->xmax != raster.bounds.xmax ||
      b->ymax != raster.bounds.ymax || raster.blocked.size() != raster.cells_per_axis * raster.cells_per_axis)
    throw std::invalid_argument("RasterPlanner: the raster was not made from this C-space's world (bounds differ)");
  return raster;
}

// The tightest admissible heuristic: octile is exact on an empty 8-connected grid of square cells
// but overestimates when cells are not square (a diagonal then costs less than max + 0.414 min),
// where the Euclidean distance is the safe choice; 4-connected paths cost the sum of the axes.
GridMetric metric_for(const Raster& r, Connectivity connectivity) {
  if (connectivity == Connectivity::axis_aligned) return GridMetric::sum_of_axes;
  return cell_width(r) == cell_height(r) ? GridMetric::octile : GridMetric::euclidean;
}

std::string text_of(const ExactPoint& p) { return "[" + to_string(p.x) + ", " + to_string(p.y) + "]"; }

// Appends p unless it repeats the last point (a start that is its cell's centre): a zero-length
// segment says nothing.
void append(std::vector<ExactPoint>& path, const ExactPoint& p) {
  if (path.empty() || !(path.back() == p)) path.push_back(p);
}

double euclidean_length(const std::vector<ExactPoint>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += std::hypot(to_double(path[i].x - path[i - 1].x), to_double(path[i].y - path[i - 1].y));
  return length;
}

}  // namespace

RasterPlanner::RasterPlanner(const Raster& raster, const CSpace& cspace, Connectivity connectivity)
    : raster_(&checked_against(raster, cspace)),
      cspace_(&cspace),
      graph_(axes_of(raster), connectivity, StepCost::euclidean, free_cells_of(raster)) {}

// An exact search in square rings of cells around p's cell (clamped into the grid), rather than a
// KD-tree in doubles: the distances are compared exactly, so ties — frequent, since starts are
// often round numbers halfway between centres — are broken by the documented rule and not by
// rounding, and the grid's arithmetic gives the neighbourhood with no index to build. A cell in
// ring r has a centre at least (r - 1/2) cell sides from p along one axis, which stops the search.
std::optional<std::pair<std::size_t, std::size_t>> RasterPlanner::nearest_free_cell(const ExactPoint& p) const {
  const Raster& r = *raster_;
  const long n = static_cast<long>(r.cells_per_axis);
  const Rational w = cell_width(r), h = cell_height(r);
  const Rational u = (p.x - r.bounds.xmin) / w, v = (p.y - r.bounds.ymin) / h;  // grid coordinates
  auto cell_of = [n](const Rational& t) -> long {
    if (t < 0) return 0;
    if (t >= n) return n - 1;
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), t.get_num_mpz_t(), t.get_den_mpz_t());
    return f.get_si();
  };
  const long i0 = cell_of(u), j0 = cell_of(v);
  const Rational shorter_side_squared = std::min(w, h) * std::min(w, h);
  const Rational half(1, 2);

  std::optional<std::pair<long, long>> best;
  Rational best_distance2;
  auto consider = [&](long i, long j) {
    if (i < 0 || j < 0 || i >= n || j >= n || r.is_blocked(i, j)) return;
    const Rational du = (i + half - u) * w, dv = (j + half - v) * h;
    const Rational d2 = du * du + dv * dv;
    const bool lower_index = best && (j < best->second || (j == best->second && i < best->first));
    if (!best || d2 < best_distance2 || (d2 == best_distance2 && lower_index)) {
      best = {i, j};
      best_distance2 = d2;
    }
  };
  for (long ring = 0; ring < n; ++ring) {
    if (best && ring >= 1) {
      const Rational reach = ring - half;
      if (reach * reach * shorter_side_squared > best_distance2) break;
    }
    for (long j = j0 - ring; j <= j0 + ring; ++j) {
      if (j == j0 - ring || j == j0 + ring) {
        for (long i = i0 - ring; i <= i0 + ring; ++i) consider(i, j);
      } else {
        consider(i0 - ring, j);
        consider(i0 + ring, j);
      }
    }
  }
  if (!best) return std::nullopt;
  return std::pair<std::size_t, std::size_t>(best->first, best->second);
}

RasterPlan RasterPlanner::plan(const Query& query, const SearchOptions& options) const {
  RasterPlan plan;
  for (const auto& [what, point] : {std::pair{"start", &query.start}, std::pair{"goal", &query.goal}})
    if (auto why = cspace_->collision_at(*point)) {
      plan.why_not_found = std::string(what) + " " + text_of(*point) + " is not free: " + *why;
      return plan;
    }
  const auto start_cell = nearest_free_cell(query.start), goal_cell = nearest_free_cell(query.goal);
  if (!start_cell || !goal_cell) {
    plan.why_not_found = "every cell of the raster is blocked";
    return plan;
  }
  std::tie(plan.start_cell_x, plan.start_cell_y) = *start_cell;
  std::tie(plan.goal_cell_x, plan.goal_cell_y) = *goal_cell;

  auto cell_id = [&](std::size_t x, std::size_t y) {
    return graph_.cell({static_cast<GridCoordinate>(x), static_cast<GridCoordinate>(y)});
  };
  const GridCell from = cell_id(plan.start_cell_x, plan.start_cell_y), to = cell_id(plan.goal_cell_x, plan.goal_cell_y);
  plan.search = shortest_path(graph_, from, to, options, GridDistanceTo(graph_, to, metric_for(*raster_, graph_.connectivity())),
                              GridMoveCost{&graph_});
  if (!plan.search.found) {
    plan.why_not_found = "no path on the " + std::to_string(raster_->cells_per_axis) + " x " +
                         std::to_string(raster_->cells_per_axis) + " grid from cell (" + std::to_string(plan.start_cell_x) +
                         ", " + std::to_string(plan.start_cell_y) + ") to cell (" + std::to_string(plan.goal_cell_x) +
                         ", " + std::to_string(plan.goal_cell_y) + ")";
    return plan;
  }
  plan.found = true;

  // A cell is a corner of the polyline only where the move direction changes.
  std::vector<std::vector<GridCoordinate>> cells;
  for (const GridCell c : plan.search.path) cells.push_back(graph_.coordinates(c));
  append(plan.path, query.start);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const bool straight_through = k > 0 && k + 1 < cells.size() && cells[k][0] - cells[k - 1][0] == cells[k + 1][0] - cells[k][0] &&
                                  cells[k][1] - cells[k - 1][1] == cells[k + 1][1] - cells[k][1];
    if (!straight_through)
      append(plan.path, raster_->cell_center(static_cast<std::size_t>(cells[k][0]), static_cast<std::size_t>(cells[k][1])));
  }
  append(plan.path, query.goal);
  plan.length = euclidean_length(plan.path);

  const PathCheck check = check_path(*cspace_, plan.path);
  plan.checked_free = check.valid;
  plan.why_not_free = check.reason;
  return plan;
}

RasterPlan plan_on_raster(const Raster& raster, const CSpace& cspace, const Query& query, const SearchOptions& options,
                          Connectivity connectivity) {
  return RasterPlanner(raster, cspace, connectivity).plan(query, options);
}

}  // namespace polyplan
