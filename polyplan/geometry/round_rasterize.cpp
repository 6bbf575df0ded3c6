#include <polyplan/geometry/round_rasterize.hpp>

#include <algorithm>
#include <functional>
#include <vector>

namespace polyplan {
namespace {

// A cell's closed square, in the world's coordinates (those of the robot's centre).
struct CellSquare {
  Rational xmin, ymin, xmax, ymax;
};

Rational squared(const Rational& a, const Rational& b) { return a * a + b * b; }

Rational squared_distance(const CellSquare& s, const ExactPoint& p) {
  const Rational dx = p.x < s.xmin ? s.xmin - p.x : p.x > s.xmax ? p.x - s.xmax : Rational(0);
  const Rational dy = p.y < s.ymin ? s.ymin - p.y : p.y > s.ymax ? p.y - s.ymax : Rational(0);
  return squared(dx, dy);
}

// The squared distance from p to the square's farthest point, a corner.
Rational squared_reach(const CellSquare& s, const ExactPoint& p) {
  const Rational dx = std::max(Rational(abs(p.x - s.xmin)), Rational(abs(p.x - s.xmax)));
  const Rational dy = std::max(Rational(abs(p.y - s.ymin)), Rational(abs(p.y - s.ymax)));
  return squared(dx, dy);
}

Rational squared_distance(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p) {
  const Rational dx = b.x - a.x, dy = b.y - a.y, length = squared(dx, dy);
  Rational t = length == 0 ? Rational(0) : ((p.x - a.x) * dx + (p.y - a.y) * dy) / length;
  t = std::clamp(t, Rational(0), Rational(1));
  return squared(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

// Whether the segment a–b meets the square, closed or open: the parameters t in [0, 1] within
// each of its four sides' half-planes (Liang–Barsky), strictly within them for the open square.
bool meets(const CellSquare& s, const ExactPoint& a, const ExactPoint& b, bool open) {
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  // Each side: p·t <= q (p·t < q for the open square).
  const std::pair<Rational, Rational> sides[] = {
      {-dx, a.x - s.xmin}, {dx, s.xmax - a.x}, {-dy, a.y - s.ymin}, {dy, s.ymax - a.y}};
  Rational low = 0, high = 1;
  bool low_strict = false, high_strict = false;  // whether t must exceed low / stay below high
  for (const auto& [p, q] : sides) {
    if (p == 0) {
      if (q < 0 || (open && q == 0)) return false;
      continue;
    }
    const Rational t = q / p;
    if (p < 0 && (t > low || (t == low && open))) low = t, low_strict = open;
    if (p > 0 && (t < high || (t == high && open))) high = t, high_strict = open;
  }
  return low < high || (low == high && !low_strict && !high_strict);
}

Rational squared_distance(const CellSquare& s, const ExactPoint& a, const ExactPoint& b) {
  if (meets(s, a, b, false)) return 0;
  // Apart, a segment and a square are nearest at an end of the one or a corner of the other.
  Rational d2 = std::min(squared_distance(s, a), squared_distance(s, b));
  for (const ExactPoint& corner :
       {ExactPoint{s.xmin, s.ymin}, ExactPoint{s.xmax, s.ymin}, ExactPoint{s.xmin, s.ymax}, ExactPoint{s.xmax, s.ymax}})
    d2 = std::min(d2, squared_distance(a, b, corner));
  return d2;
}

// What one obstacle's core blocks: the box beyond which it blocks no cell, and the exact test of
// a cell's square.
struct Blocker {
  Bounds reach;
  std::function<bool(const CellSquare&)> blocks;
};

Bounds grown_box(const std::vector<ExactPoint>& points, const Rational& by) {
  Bounds b{points[0].x, points[0].y, points[0].x, points[0].y};
  for (const ExactPoint& p : points) {
    b.xmin = std::min(b.xmin, p.x), b.ymin = std::min(b.ymin, p.y);
    b.xmax = std::max(b.xmax, p.x), b.ymax = std::max(b.ymax, p.y);
  }
  return {b.xmin - by, b.ymin - by, b.xmax + by, b.ymax + by};
}

// A segment of a wall or a polygon's edge grown by the robot's radius r; r = 0: a wall's piece
// blocks every square it meets (crossing it is never allowed, so no cell may straddle it), a
// polygon's edge every square whose interior it passes (that square holds points inside).
Blocker segment_blocker(const ExactPoint& a, const ExactPoint& b, const Rational& r, bool wall) {
  return {grown_box({a, b}, r), [a, b, r, wall](const CellSquare& s) {
            if (r == 0) return meets(s, a, b, !wall);
            return squared_distance(s, a, b) < r * r;
          }};
}

std::vector<Blocker> blockers(const RoundCSpace& space) {
  std::vector<Blocker> out;
  for (const RoundCore& core : space.obstacles) {
    const Rational& r = core.radius;
    if (core.kind == RoundCore::Kind::point) {
      const ExactPoint centre = core.points[0];
      out.push_back(
          {grown_box({centre}, r), [centre, r](const CellSquare& s) { return squared_distance(s, centre) < r * r; }});
    }
    if (core.kind == RoundCore::Kind::wall)
      for (std::size_t k = 0; k + 1 < core.points.size(); ++k)
        out.push_back(segment_blocker(core.points[k], core.points[k + 1], r, true));
    for (const Ring& ring : core.rings)
      for (std::size_t k = 0; k < ring.size(); ++k)
        out.push_back(segment_blocker(ring[k], ring[(k + 1) % ring.size()], r, false));
  }
  return out;
}

// The rasterising state: the raster and the squares of its cells.
class RoundRasterizer {
 public:
  RoundRasterizer(const RoundWorld& world, Raster& raster) : world_(world), raster_(raster) {
    const std::size_t n = raster.cells_per_axis;
    const Rational w = raster.cell_width(), h = raster.cell_height();
    for (std::size_t k = 0; k <= n; ++k) {
      xs_.push_back(raster.bounds.xmin + w * Rational(mpz_class(k)));
      ys_.push_back(raster.bounds.ymin + h * Rational(mpz_class(k)));
    }
  }

  CellSquare square(long i, long j) const { return {xs_[i], ys_[j], xs_[i + 1], ys_[j + 1]}; }

  // Calls `decide(i, j)` for every cell not blocked yet whose square meets `box`.
  template <class Decide>
  void each_open_cell_meeting(const Bounds& box, Decide&& decide) {
    const auto window = cells_meeting(raster_, box);
    if (!window) return;
    const long n = static_cast<long>(raster_.cells_per_axis);
    for (long j = window->j0; j <= window->j1; ++j)
      for (long i = window->i0; i <= window->i1; ++i)
        if (!raster_.blocked[i + j * n] && decide(i, j)) raster_.blocked[i + j * n] = 1;
  }

  // The cells outside the disc where the centre may be (the disc bounds shrunk by the robot's
  // radius), walls as the box's are.
  void block_outside(const Disc& inside) {
    const long n = static_cast<long>(raster_.cells_per_axis);
    for (long j = 0; j < n; ++j)
      for (long i = 0; i < n; ++i)
        if (inside.radius < 0 || squared_reach(square(i, j), inside.center) > inside.radius * inside.radius)
          raster_.blocked[i + j * n] = raster_.walls[i + j * n] = 1;
  }

  void block_near_obstacles() {
    for (const Blocker& b : blockers(world_.cspace()))
      each_open_cell_meeting(b.reach, [&](long i, long j) { return b.blocks(square(i, j)); });
    // A square near no edge of a polygon lies inside it or apart from it: its centre says which.
    for (const RoundCore& core : world_.cspace().obstacles)
      if (core.kind == RoundCore::Kind::polygon)
        each_open_cell_meeting(grown_box(core.rings[0], core.radius), [&](long i, long j) {
          return world_.config_not_free(raster_.cell_center(i, j)).has_value();
        });
  }

 private:
  const RoundWorld& world_;
  Raster& raster_;
  std::vector<Rational> xs_, ys_;  // the grid's lines, n + 1 each
};

}  // namespace

Raster rasterize(const RoundWorld& world, std::size_t cells_per_axis) {
  Raster raster = empty_raster(world.world(), cells_per_axis);
  if (world.reference_box()) block_outside_box(*world.reference_box(), raster);
  RoundRasterizer cells(world, raster);
  if (world.reference_disc()) cells.block_outside(*world.reference_disc());
  cells.block_near_obstacles();
  return raster;
}

}  // namespace polyplan
