#include <polyplan/geometry/rasterize.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <string>

namespace polyplan {
namespace {

// The work happens in grid coordinates, where cell (i, j) is the unit square (i, i+1) × (j, j+1):
// an exact affine map of the world (rationals), so every incidence is preserved and each cell
// test is a comparison with integers.
struct GridPoint {
  Rational u, v;
};

class GridFrame {
 public:
  GridFrame(const Bounds& b, std::size_t n)
      : xmin_(b.xmin), ymin_(b.ymin), su_(Rational(mpz_class(n)) / (b.xmax - b.xmin)),
        sv_(Rational(mpz_class(n)) / (b.ymax - b.ymin)) {}
  GridPoint to_grid(const ExactPoint& p) const { return {(p.x - xmin_) * su_, (p.y - ymin_) * sv_}; }

 private:
  Rational xmin_, ymin_, su_, sv_;
};

long floor_of(const Rational& q) {
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return f.get_si();
}
long ceil_of(const Rational& q) {
  mpz_class c;
  mpz_cdiv_q(c.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return c.get_si();
}

// The cells whose open interval (k, k+1) meets the closed interval [lo, hi], clamped to [0, n):
// k < hi and k + 1 > lo. Empty (first > last) for a degenerate interval on a grid line.
std::pair<long, long> open_cells_meeting(const Rational& lo, const Rational& hi, long n) {
  if (hi <= 0 || lo >= n) return {0, -1};
  // Clamped before converting: an obstacle far beyond the bounds must not overflow `long`.
  return {lo <= 0 ? 0L : floor_of(lo), hi >= n ? n - 1 : ceil_of(hi) - 1};
}

// Blocks every cell whose open square an edge of the ring passes through. Such a square holds
// points on both sides of the edge, so it meets the C-obstacle's interior (every boundary point
// of a regularized set is a limit of interior points).
//
// Column by column: the edge's piece in the closed column [i, i+1] spans [vlo, vhi], and the
// edge meets the open square (i, i+1) × (j, j+1) exactly when j < vhi and j + 1 > vlo. (A value
// strictly inside both (vlo, vhi) and (j, j+1) is taken by the piece at a u strictly inside its
// own u-range, hence strictly inside the column; a horizontal piece needs vlo in (j, j+1), and a
// vertical edge strictly inside a column gets that column only.) So the enumeration is the exact
// test itself, and a long diagonal edge costs the cells along it, not its bounding box.
void block_cells_crossed_by(const std::vector<GridPoint>& ring, long n, std::vector<std::uint8_t>& blocked) {
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const GridPoint& a = ring[k];
    const GridPoint& b = ring[(k + 1) % ring.size()];
    const Rational du = b.u - a.u, dv = b.v - a.v;
    const auto [first_column, last_column] = open_cells_meeting(std::min(a.u, b.u), std::max(a.u, b.u), n);
    for (long i = first_column; i <= last_column; ++i) {
      Rational vlo = std::min(a.v, b.v), vhi = std::max(a.v, b.v);
      if (du != 0) {
        const Rational u0 = std::max(Rational(i), std::min(a.u, b.u));
        const Rational u1 = std::min(Rational(i + 1), std::max(a.u, b.u));
        const Rational v0 = a.v + (u0 - a.u) * dv / du, v1 = a.v + (u1 - a.u) * dv / du;
        vlo = std::min(v0, v1);
        vhi = std::max(v0, v1);
      }
      const auto [first_row, last_row] = open_cells_meeting(vlo, vhi, n);
      for (long j = first_row; j <= last_row; ++j) blocked[static_cast<std::size_t>(i + j * n)] = 1;
    }
  }
}

}  // namespace

ExactPoint Raster::cell_center(std::size_t x, std::size_t y) const {
  const Rational twice_n(mpz_class(2 * cells_per_axis));
  return {bounds.xmin + Rational(mpz_class(2 * x + 1)) * (bounds.xmax - bounds.xmin) / twice_n,
          bounds.ymin + Rational(mpz_class(2 * y + 1)) * (bounds.ymax - bounds.ymin) / twice_n};
}

Rational Raster::cell_width() const { return (bounds.xmax - bounds.xmin) / Rational(mpz_class(cells_per_axis)); }
Rational Raster::cell_height() const { return (bounds.ymax - bounds.ymin) / Rational(mpz_class(cells_per_axis)); }

std::size_t Raster::blocked_count() const {
  return static_cast<std::size_t>(std::count(blocked.begin(), blocked.end(), std::uint8_t{1}));
}

std::optional<CellWindow> cells_meeting(const Raster& raster, const Bounds& box) {
  const long n = static_cast<long>(raster.cells_per_axis);
  const GridFrame frame(raster.bounds, raster.cells_per_axis);
  const GridPoint low = frame.to_grid({box.xmin, box.ymin}), high = frame.to_grid({box.xmax, box.ymax});
  if (high.u < 0 || high.v < 0 || low.u > n || low.v > n) return std::nullopt;
  // Cell k's closed interval [k, k+1] meets [low, high] when low - 1 <= k <= high; clamped before
  // converting, so that a box far beyond the grid does not overflow `long`.
  const auto first = [n](const Rational& t) { return t <= 0 ? 0L : std::min(ceil_of(t) - 1, n - 1); };
  const auto last = [n](const Rational& t) { return t >= n ? n - 1 : std::max(floor_of(t), 0L); };
  return CellWindow{first(low.u), first(low.v), last(high.u), last(high.v)};
}

namespace {

// Decides every cell of `window` whose square lies inside the reference box (the walls were set
// already): blocked when its square meets the interior of a C-obstacle of `cspace`.
void decide_cells(const CSpace& cspace, const GridFrame& frame, const CellWindow& window, Raster& raster) {
  const long n = static_cast<long>(raster.cells_per_axis);
  // (a) Cells an edge of a C-obstacle passes through. (Edges outside the window block the cells
  // they blocked before: outside it the C-obstacles are the same point set.)
  struct GridBox {
    Rational umin, vmin, umax, vmax;
  };
  std::vector<GridBox> outer_boxes;
  for (const PolygonWithHoles& c : cspace.cobstacles()) {
    auto to_grid = [&](const Ring& ring) {
      std::vector<GridPoint> out;
      out.reserve(ring.size());
      for (const ExactPoint& p : ring) out.push_back(frame.to_grid(p));
      return out;
    };
    if (!c.outer.empty()) {
      const std::vector<GridPoint> outer = to_grid(c.outer);
      GridBox b{outer[0].u, outer[0].v, outer[0].u, outer[0].v};
      for (const GridPoint& p : outer) {
        b.umin = std::min(b.umin, p.u), b.vmin = std::min(b.vmin, p.v);
        b.umax = std::max(b.umax, p.u), b.vmax = std::max(b.vmax, p.v);
      }
      outer_boxes.push_back(b);
      block_cells_crossed_by(outer, n, raster.blocked);
    }
    for (const Ring& hole : c.holes) block_cells_crossed_by(to_grid(hole), n, raster.blocked);
  }

  // (b) Every square not blocked yet meets no C-obstacle edge and lies inside the reference box:
  // it lies in one face of the free space's arrangement, free or inside a C-obstacle. Its centre
  // decides, by exact point location; only centres inside some C-obstacle's bounding box can be
  // inside it.
  for (long j = window.j0; j <= window.j1; ++j)
    for (long i = window.i0; i <= window.i1; ++i) {
      const std::size_t cell = static_cast<std::size_t>(i + j * n);
      if (raster.blocked[cell]) continue;
      const Rational cu = Rational(2 * i + 1, 2), cv = Rational(2 * j + 1, 2);
      const bool maybe_inside = std::any_of(outer_boxes.begin(), outer_boxes.end(), [&](const GridBox& b) {
        return b.umin < cu && cu < b.umax && b.vmin < cv && cv < b.vmax;
      });
      if (maybe_inside && cspace.locate(raster.cell_center(i, j)).kind == Location::Kind::blocked)
        raster.blocked[cell] = 1;
    }
}

// A box holding the C-obstacle of `obstacle`: its outer ring's box grown by the robot reflected
// through its reference point (O ⊕ −R), as every C-obstacle is.
Bounds cobstacle_box(const PolygonWithHoles& polygon, const Robot& robot) {
  const ExactPoint& first = polygon.outer.front();
  Bounds obstacle{first.x, first.y, first.x, first.y};
  for (const ExactPoint& p : polygon.outer) {
    obstacle.xmin = std::min(obstacle.xmin, p.x), obstacle.ymin = std::min(obstacle.ymin, p.y);
    obstacle.xmax = std::max(obstacle.xmax, p.x), obstacle.ymax = std::max(obstacle.ymax, p.y);
  }
  Bounds grown = obstacle;
  for (const Ring& part : robot.parts)
    for (const ExactPoint& p : part) {
      const Rational xmin = obstacle.xmin - p.x, xmax = obstacle.xmax - p.x;
      const Rational ymin = obstacle.ymin - p.y, ymax = obstacle.ymax - p.y;
      grown.xmin = std::min(grown.xmin, xmin), grown.xmax = std::max(grown.xmax, xmax);
      grown.ymin = std::min(grown.ymin, ymin), grown.ymax = std::max(grown.ymax, ymax);
    }
  return grown;
}

}  // namespace

Raster empty_raster(const World& world, std::size_t cells_per_axis) {
  if (!world.bounds && !world.disc_bounds)
    throw InputError(world.source + ": bounds: a raster needs the world's bounds (the file has none)");
  if (cells_per_axis == 0 || cells_per_axis > max_cells_per_axis)
    throw InputError(world.source + ": raster: cells per axis must be between 1 and " +
                     std::to_string(max_cells_per_axis) + ", got " + std::to_string(cells_per_axis));
  Bounds box;
  if (world.bounds) box = *world.bounds;
  else {
    const Disc& d = *world.disc_bounds;
    box = {d.center.x - d.radius, d.center.y - d.radius, d.center.x + d.radius, d.center.y + d.radius};
  }
  const std::vector<std::uint8_t> none(cells_per_axis * cells_per_axis, 0);
  return Raster{box, cells_per_axis, none, none};
}

void block_outside_box(const Bounds& box, Raster& raster) {
  const long n = static_cast<long>(raster.cells_per_axis);
  const GridFrame frame(raster.bounds, raster.cells_per_axis);
  const GridPoint box_low = frame.to_grid({box.xmin, box.ymin}), box_high = frame.to_grid({box.xmax, box.ymax});
  std::vector<std::uint8_t> column_inside(raster.cells_per_axis), row_inside(raster.cells_per_axis);
  for (long k = 0; k < n; ++k) {
    column_inside[k] = box_low.u <= k && k + 1 <= box_high.u;
    row_inside[k] = box_low.v <= k && k + 1 <= box_high.v;
  }
  for (long j = 0; j < n; ++j)
    for (long i = 0; i < n; ++i)
      if (!column_inside[i] || !row_inside[j]) raster.blocked[i + j * n] = raster.walls[i + j * n] = 1;
}

Raster rasterize(const CSpace& cspace, std::size_t cells_per_axis) {
  Raster raster = empty_raster(cspace.world(), cells_per_axis);
  const long n = static_cast<long>(cells_per_axis);
  block_outside_box(*cspace.reference_box(), raster);
  decide_cells(cspace, GridFrame(raster.bounds, cells_per_axis), {0, 0, n - 1, n - 1}, raster);
  return raster;
}

Raster rasterize_change(const CSpace& after, const Raster& before,
                        const std::vector<const PolygonWithHoles*>& changed) {
  Raster raster = before;
  const long n = static_cast<long>(raster.cells_per_axis);
  const GridFrame frame(raster.bounds, raster.cells_per_axis);
  for (const PolygonWithHoles* obstacle : changed) {
    // Cells whose closed square meets the C-obstacle's closed box: elsewhere a square and a
    // neighbourhood of it miss the change, so the union's interior there is as it was.
    const std::optional<CellWindow> meeting = cells_meeting(raster, cobstacle_box(*obstacle, after.world().robot));
    if (!meeting) continue;
    const CellWindow& window = *meeting;
    for (long j = window.j0; j <= window.j1; ++j)
      for (long i = window.i0; i <= window.i1; ++i) raster.blocked[i + j * n] = raster.walls[i + j * n];
    decide_cells(after, frame, window, raster);
  }
  return raster;
}

Raster rasterize(const World& world, std::size_t cells_per_axis) {
  empty_raster(world, cells_per_axis);  // its refusals before the costly C-space
  return rasterize(CSpace(world), cells_per_axis);
}

// An exact search in square rings of cells around p's cell (clamped into the grid), rather than a
// KD-tree in doubles: the distances are compared exactly, so ties — frequent, since starts are
// often round numbers halfway between centres — are broken by the documented rule and not by
// rounding, and the grid's arithmetic gives the neighbourhood with no index to build. A cell in
// ring r has a centre at least (r - 1/2) cell sides from p along one axis, which stops the search.
std::optional<std::pair<std::size_t, std::size_t>> nearest_free_cell(const Raster& r, const ExactPoint& p) {
  const long n = static_cast<long>(r.cells_per_axis);
  const Rational w = r.cell_width(), h = r.cell_height();
  const Rational u = (p.x - r.bounds.xmin) / w, v = (p.y - r.bounds.ymin) / h;  // grid coordinates
  auto cell_of = [n](const Rational& t) -> long {
    if (t < 0) return 0;
    if (t >= n) return n - 1;
    return floor_of(t);
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

}  // namespace polyplan
