#include <polyplan/free_space/detail/integer_triangulation.hpp>

#include <polyplan/free_space/detail/free_space_triangulation.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan::detail {
namespace {

constexpr int ccw(int i) { return i == 2 ? 0 : i + 1; }
constexpr int cw(int i) { return i == 0 ? 2 : i - 1; }

IntegerPoint operator-(const IntegerPoint& a, const IntegerPoint& b) { return {a.x - b.x, a.y - b.y}; }
std::int64_t dot(const IntegerPoint& a, const IntegerPoint& b) { return a.x * b.x + a.y * b.y; }
std::int64_t cross_product(const IntegerPoint& a, const IntegerPoint& b) { return a.x * b.y - a.y * b.x; }

// Directions ordered counter-clockwise from the positive x axis, as CGAL orders Direction_2.
int half(const IntegerPoint& d) { return d.y < 0 || (d.y == 0 && d.x < 0) ? 1 : 0; }
bool angle_less(const IntegerPoint& a, const IntegerPoint& b) {
  const int ha = half(a), hb = half(b);
  return ha != hb ? ha < hb : cross_product(a, b) > 0;
}
bool same_direction(const IntegerPoint& a, const IntegerPoint& b) { return cross_product(a, b) == 0 && dot(a, b) > 0; }

std::optional<std::int64_t> integer(const FT& value) {
  const Rational q = to_rational(value);
  if (q.get_den() != 1 || abs(q.get_num()) >= kIntegerCoordinateLimit) return std::nullopt;
  return static_cast<std::int64_t>(q.get_num().get_si());
}

}  // namespace

std::optional<IntegerTriangulation> IntegerTriangulation::from(const FreeSpaceTriangulation& source) {
  const FreeSpaceTriangulation::Arrays arrays = source.arrays();
  Parts parts;
  parts.space_vertices = source.vertex_count();
  for (const Point& p : arrays.points) {
    const auto x = integer(p.x()), y = integer(p.y());
    if (!x || !y) return std::nullopt;
    parts.points.push_back({*x, *y});
  }
  for (const auto& s : arrays.triangles) {
    Parts::Triangle triangle{};
    for (int i = 0; i < 3; ++i) {
      triangle.vertex[i] = s.vertex[i];
      triangle.neighbour[i] = s.neighbour[i];
      triangle.constrained[i] = s.constrained[i];
    }
    triangle.free = s.free;
    triangle.component = s.component;
    parts.triangles.push_back(triangle);
  }
  for (std::size_t v = 0; v < parts.space_vertices; ++v) {
    const VertexWedges& w = source.wedges(v);
    auto& edges = parts.wedges.emplace_back();
    for (std::size_t k = 0; k < w.size(); ++k) {
      const auto x = integer(w.far(k).x()), y = integer(w.far(k).y());
      if (!x || !y) return std::nullopt;
      edges.push_back({IntegerPoint{*x, *y} - parts.points[v], w.is_free(k)});
    }
  }
  return assemble(parts);
}

IntegerTriangulation IntegerTriangulation::assemble(const Parts& parts) {
  IntegerTriangulation t;
  t.space_vertices_ = parts.space_vertices;
  t.points_ = parts.points;
  for (const Parts::Triangle& s : parts.triangles) {
    Triangle triangle{};
    for (int i = 0; i < 3; ++i) {
      triangle.vertex[i] = s.vertex[i];
      triangle.neighbour[i] = s.neighbour[i];
      triangle.constrained |= static_cast<std::uint8_t>(s.constrained[i] ? 1 << i : 0);
    }
    triangle.free = s.free;
    triangle.component = s.component;
    t.triangles_.push_back(triangle);
  }
  // Fans: the triangles around each vertex, counted then placed (compressed rows).
  t.fan_begin_.assign(t.points_.size() + 1, 0);
  for (const Triangle& triangle : t.triangles_)
    for (int v : triangle.vertex) ++t.fan_begin_[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < t.points_.size(); ++v) t.fan_begin_[v + 1] += t.fan_begin_[v];
  t.fan_.resize(t.fan_begin_.back());
  std::vector<std::size_t> fill(t.fan_begin_.begin(), t.fan_begin_.end() - 1);
  for (std::size_t i = 0; i < t.triangles_.size(); ++i)
    for (int v : t.triangles_[i].vertex) t.fan_[fill[static_cast<std::size_t>(v)]++] = static_cast<int>(i);
  t.wedge_begin_.push_back(0);
  for (const auto& edges : parts.wedges) {
    t.wedges_.insert(t.wedges_.end(), edges.begin(), edges.end());
    t.wedge_begin_.push_back(t.wedges_.size());
  }
  // Point location: about two triangles per bucket; each bucket keeps the triangle that a walk
  // from its neighbour's found at its centre.
  if (t.triangles_.empty() || t.points_.empty()) return t;
  t.low_ = t.high_ = t.points_.front();
  for (const IntegerPoint& p : t.points_) {
    t.low_ = {std::min(t.low_.x, p.x), std::min(t.low_.y, p.y)};
    t.high_ = {std::max(t.high_.x, p.x), std::max(t.high_.y, p.y)};
  }
  const auto side = static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(t.triangles_.size()) / 2)));
  const std::int64_t span = std::max(t.high_.x - t.low_.x, t.high_.y - t.low_.y);
  t.bucket_size_ = std::max<std::int64_t>(1, (span + side - 1) / std::max<std::int64_t>(side, 1));
  t.buckets_x_ = static_cast<int>((t.high_.x - t.low_.x) / t.bucket_size_ + 1);
  t.buckets_y_ = static_cast<int>((t.high_.y - t.low_.y) / t.bucket_size_ + 1);
  t.bucket_triangle_.assign(static_cast<std::size_t>(t.buckets_x_) * t.buckets_y_, 0);
  int from = 0;
  for (int by = 0; by < t.buckets_y_; ++by)
    for (int i = 0; i < t.buckets_x_; ++i) {
      const int bx = by % 2 == 0 ? i : t.buckets_x_ - 1 - i;  // snake order: each walk is short
      const IntegerPoint centre{std::min(t.high_.x, t.low_.x + bx * t.bucket_size_ + t.bucket_size_ / 2),
                                std::min(t.high_.y, t.low_.y + by * t.bucket_size_ + t.bucket_size_ / 2)};
      const Location found = t.locate_from(from, centre);
      if (found.triangle >= 0) from = found.triangle;
      t.bucket_triangle_[static_cast<std::size_t>(by) * t.buckets_x_ + bx] = from;
    }
  return t;
}

std::size_t IntegerTriangulation::memory_bytes() const {
  return points_.capacity() * sizeof(IntegerPoint) + triangles_.capacity() * sizeof(Triangle) +
         (fan_begin_.capacity() + wedge_begin_.capacity()) * sizeof(std::size_t) + fan_.capacity() * sizeof(int) +
         wedges_.capacity() * sizeof(WedgeEdge) + bucket_triangle_.capacity() * sizeof(int);
}

bool IntegerTriangulation::in_closed_triangle(int triangle, const IntegerPoint& q) const {
  const Triangle& t = triangles_[static_cast<std::size_t>(triangle)];
  for (int i = 0; i < 3; ++i)
    if (orientation(points_[static_cast<std::size_t>(t.vertex[ccw(i)])],
                    points_[static_cast<std::size_t>(t.vertex[cw(i)])], q) < 0)
      return false;
  return true;
}

// A visibility walk (cross any edge that has p strictly beyond it), the edge tried first chosen
// at random: a constrained triangulation need not be Delaunay, where a fixed order can cycle.
IntegerTriangulation::Location IntegerTriangulation::locate_from(int triangle, const IntegerPoint& p) const {
  auto classify = [&](int t) {
    const Triangle& tri = triangles_[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i)
      if (points_[static_cast<std::size_t>(tri.vertex[i])] == p) return Location{Location::vertex, t, tri.vertex[i]};
    for (int i = 0; i < 3; ++i)
      if (orientation(points_[static_cast<std::size_t>(tri.vertex[ccw(i)])],
                      points_[static_cast<std::size_t>(tri.vertex[cw(i)])], p) == 0)
        return Location{Location::edge, t, i};
    return Location{Location::face, t, -1};
  };
  std::uint64_t random =
      static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(p.y) * 0xC2B2AE3D27D4EB4FULL;
  for (std::size_t steps = 0; steps < 4 * triangles_.size() + 16; ++steps) {
    const Triangle& t = triangles_[static_cast<std::size_t>(triangle)];
    random = random * 6364136223846793005ULL + 1442695040888963407ULL;
    const int first = static_cast<int>((random >> 33) % 3);
    int beyond = -1;
    for (int k = 0; k < 3 && beyond < 0; ++k) {
      const int i = (first + k) % 3;
      if (orientation(points_[static_cast<std::size_t>(t.vertex[ccw(i)])],
                      points_[static_cast<std::size_t>(t.vertex[cw(i)])], p) < 0)
        beyond = i;
    }
    if (beyond < 0) return classify(triangle);
    if (t.neighbour[beyond] < 0) return {};  // beyond the convex hull
    triangle = t.neighbour[beyond];
  }
  for (std::size_t t = 0; t < triangles_.size(); ++t)  // cannot happen; a scan is still right
    if (in_closed_triangle(static_cast<int>(t), p)) return classify(static_cast<int>(t));
  return {};
}

IntegerTriangulation::Location IntegerTriangulation::locate(const IntegerPoint& p) const {
  if (triangles_.empty() || p.x < low_.x || p.y < low_.y || p.x > high_.x || p.y > high_.y) return {};
  const auto bx = static_cast<std::size_t>((p.x - low_.x) / bucket_size_),
             by = static_cast<std::size_t>((p.y - low_.y) / bucket_size_);
  return locate_from(bucket_triangle_[by * static_cast<std::size_t>(buckets_x_) + bx], p);
}

bool IntegerTriangulation::is_reflex_wedge(std::size_t v, std::size_t k) const {
  const std::size_t n = wedge_count(v);
  return cross_product(wedges_[wedge_begin_[v] + k].direction, wedges_[wedge_begin_[v] + (k + 1) % n].direction) < 0;
}

bool IntegerTriangulation::is_pinch(std::size_t v) const {
  return std::count_if(wedges_.begin() + static_cast<std::ptrdiff_t>(wedge_begin_[v]),
                       wedges_.begin() + static_cast<std::ptrdiff_t>(wedge_begin_[v + 1]),
                       [](const WedgeEdge& e) { return e.free_on_left; }) >= 2;
}

std::optional<std::size_t> IntegerTriangulation::wedge(std::size_t v, const IntegerPoint& d) const {
  const auto first = wedges_.begin() + static_cast<std::ptrdiff_t>(wedge_begin_[v]);
  const auto last = wedges_.begin() + static_cast<std::ptrdiff_t>(wedge_begin_[v + 1]);
  const std::size_t n = static_cast<std::size_t>(last - first);
  const auto after = std::upper_bound(
      first, last, d, [](const IntegerPoint& dir, const WedgeEdge& e) { return angle_less(dir, e.direction); });
  std::size_t k = after == first ? n - 1 : static_cast<std::size_t>(after - first) - 1;
  if (same_direction(first[static_cast<std::ptrdiff_t>(k)].direction, d) &&
      !first[static_cast<std::ptrdiff_t>(k)].free_on_left)
    k = (k + n - 1) % n;
  if (!first[static_cast<std::ptrdiff_t>(k)].free_on_left) return std::nullopt;
  return k;
}

template <typename Visit>
void IntegerTriangulation::for_each_triangle_at(const Location& where, Visit visit) const {
  switch (where.type) {
    case Location::face: visit(where.triangle); break;
    case Location::edge: {
      visit(where.triangle);
      const int other = triangles_[static_cast<std::size_t>(where.triangle)].neighbour[where.index];
      if (other >= 0) visit(other);
      break;
    }
    case Location::vertex: {
      const auto v = static_cast<std::size_t>(where.index);
      for (std::size_t i = fan_begin_[v]; i < fan_begin_[v + 1]; ++i) visit(fan_[i]);
      break;
    }
    default: break;
  }
}

void IntegerTriangulation::begin(Scratch& scratch) const {
  if (scratch.seen.size() != space_vertices_) {
    scratch.seen.assign(space_vertices_, 0);
    scratch.generation = 0;
  }
  if (++scratch.generation == 0) {  // wrapped: clear for real once every 4 billion walks
    std::fill(scratch.seen.begin(), scratch.seen.end(), 0);
    scratch.generation = 1;
  }
}

void IntegerTriangulation::report(int vertex, std::vector<int>& out, Scratch& scratch) const {
  const auto v = static_cast<std::size_t>(vertex);
  if (v >= space_vertices_ || scratch.seen[v] == scratch.generation) return;
  scratch.seen[v] = scratch.generation;
  out.push_back(vertex);
}

// Enters the triangle across `edge` with the part of the cone (right, left) that crosses the
// edge's interior, keeping a positive width (free_space_triangulation.cpp's `narrow` says why).
void IntegerTriangulation::cross(const IntegerPoint& apex, int triangle, int edge, const IntegerPoint& right,
                                 const IntegerPoint& left, Scratch& scratch) const {
  const Triangle& t = triangles_[static_cast<std::size_t>(triangle)];
  if (t.is_constrained(edge)) return;
  const IntegerPoint& a = points_[static_cast<std::size_t>(t.vertex[ccw(edge)])];
  const IntegerPoint& b = points_[static_cast<std::size_t>(t.vertex[cw(edge)])];
  const int turn = orientation(apex, a, b);
  if (turn == 0) return;  // seen end-on
  const IntegerPoint& r = turn > 0 ? a : b;
  const IntegerPoint& l = turn > 0 ? b : a;
  const IntegerPoint narrow_right = orientation(apex, right, r) > 0 ? r : right;
  const IntegerPoint narrow_left = orientation(apex, left, l) < 0 ? l : left;
  if (orientation(apex, narrow_right, narrow_left) <= 0) return;
  const int next = t.neighbour[edge];
  if (next < 0 || !triangles_[static_cast<std::size_t>(next)].free) return;
  const Triangle& n = triangles_[static_cast<std::size_t>(next)];
  const int entry = n.neighbour[0] == triangle ? 0 : n.neighbour[1] == triangle ? 1 : 2;
  scratch.stack.push_back({next, entry, narrow_right, narrow_left});
}

void IntegerTriangulation::expand(const IntegerPoint& apex, std::vector<int>& out, Scratch& scratch) const {
  while (!scratch.stack.empty()) {
    const Scratch::Step step = scratch.stack.back();
    scratch.stack.pop_back();
    const Triangle& t = triangles_[static_cast<std::size_t>(step.triangle)];
    const int far = t.vertex[step.entry];
    const IntegerPoint& q = points_[static_cast<std::size_t>(far)];
    if (orientation(apex, step.right, q) >= 0 && orientation(apex, step.left, q) <= 0) report(far, out, scratch);
    cross(apex, step.triangle, ccw(step.entry), step.right, step.left, scratch);
    cross(apex, step.triangle, cw(step.entry), step.right, step.left, scratch);
  }
}

void IntegerTriangulation::expand_from(const IntegerPoint& apex, int triangle, std::vector<int>& out,
                                       Scratch& scratch) const {
  const Triangle& t = triangles_[static_cast<std::size_t>(triangle)];
  for (int i = 0; i < 3; ++i) {
    report(t.vertex[i], out, scratch);
    const IntegerPoint& a = points_[static_cast<std::size_t>(t.vertex[ccw(i)])];
    const IntegerPoint& b = points_[static_cast<std::size_t>(t.vertex[cw(i)])];
    const int turn = orientation(apex, a, b);
    if (turn != 0) cross(apex, triangle, i, turn > 0 ? a : b, turn > 0 ? b : a, scratch);
  }
  expand(apex, out, scratch);
}

bool IntegerTriangulation::visible_from_point(const IntegerPoint& p, const Location& where, std::vector<int>& out,
                                              Scratch& scratch) const {
  begin(scratch);
  if (where.type == Location::vertex && static_cast<std::size_t>(where.index) < space_vertices_)
    scratch.seen[static_cast<std::size_t>(where.index)] = scratch.generation;  // a viewpoint does not see itself
  bool any_free = false;
  for_each_triangle_at(where, [&](int t) {
    if (!triangles_[static_cast<std::size_t>(t)].free) return;
    any_free = true;
    expand_from(p, t, out, scratch);
  });
  return any_free;
}

void IntegerTriangulation::visible_from_corner(std::size_t v, std::size_t wedge_index, std::vector<int>& out,
                                               Scratch& scratch) const {
  begin(scratch);
  scratch.seen[v] = scratch.generation;
  const IntegerPoint& apex = points_[v];
  for (std::size_t f = fan_begin_[v]; f < fan_begin_[v + 1]; ++f) {
    const int triangle = fan_[f];
    const Triangle& t = triangles_[static_cast<std::size_t>(triangle)];
    if (!t.free) continue;
    const int i = t.vertex[0] == static_cast<int>(v) ? 0 : t.vertex[1] == static_cast<int>(v) ? 1 : 2;
    const int a = t.vertex[ccw(i)], b = t.vertex[cw(i)];
    if (wedge(v, points_[static_cast<std::size_t>(a)] - apex) != wedge_index) continue;
    report(a, out, scratch);
    report(b, out, scratch);
    cross(apex, triangle, i, points_[static_cast<std::size_t>(a)], points_[static_cast<std::size_t>(b)], scratch);
    expand(apex, out, scratch);
  }
}

void IntegerTriangulation::components_at(const Location& where, std::vector<int>& out) const {
  out.clear();
  for_each_triangle_at(where, [&](int t) {
    const Triangle& triangle = triangles_[static_cast<std::size_t>(t)];
    if (triangle.free && std::find(out.begin(), out.end(), triangle.component) == out.end())
      out.push_back(triangle.component);
  });
}

// free_space_triangulation.cpp's why_blocked, step for step, in integers.
IntegerTriangulation::Blocked IntegerTriangulation::walk(const IntegerPoint& a, const Location& from,
                                                         const IntegerPoint& b) const {
  if (a == b) {
    bool any_free = false;
    for_each_triangle_at(from, [&](int t) { any_free |= triangles_[static_cast<std::size_t>(t)].free; });
    return any_free ? Blocked{} : Blocked{Blocked::point_blocked};
  }
  const IntegerPoint direction = b - a;
  auto ahead = [&](const IntegerPoint& q) { return dot(q - a, direction) > 0; };
  auto on_segment_before = [&](const IntegerPoint& q, const IntegerPoint& far) {  // b on [q, far]?
    return orientation(q, far, b) == 0 && dot(b - q, far - q) >= 0 && dot(b - far, q - far) >= 0;
  };
  auto at_point = [&](int v) -> const IntegerPoint& { return points_[static_cast<std::size_t>(v)]; };
  int face = -1;       // the triangle the segment runs into, or
  int at = -1;         // the vertex the segment passes through
  int came_from = -1;  // the vertex we left the last time, if any
  bool arrived = false;
  switch (from.type) {
    case Location::face: face = from.triangle; break;
    case Location::vertex: at = from.index; break;
    case Location::edge: {
      const Triangle& t = triangles_[static_cast<std::size_t>(from.triangle)];
      const int other = t.neighbour[from.index];
      if (!t.free && (other < 0 || !triangles_[static_cast<std::size_t>(other)].free)) return {Blocked::starts_inside};
      const int u = t.vertex[ccw(from.index)], w = t.vertex[cw(from.index)];
      const int side = orientation(at_point(u), at_point(w), b);
      if (side == 0) {  // along the edge, towards u or w
        at = ahead(at_point(u)) ? u : w;
        if (on_segment_before(a, at_point(at))) return {};
        arrived = true;
      } else {
        face = side > 0 ? from.triangle : other;
        if (face < 0) return {Blocked::enters};
      }
      break;
    }
    default: return {Blocked::start_outside};
  }

  for (std::size_t steps = 0; steps < 4 * triangles_.size() + 8; ++steps) {
    if (at >= 0) {
      if (at_point(at) == b) return {};
      if (static_cast<std::size_t>(at) >= space_vertices_) return {Blocked::frame};
      const auto leaving = wedge(static_cast<std::size_t>(at), direction);
      if (!leaving) return {Blocked::enters_at, at};
      if (arrived && wedge(static_cast<std::size_t>(at), a - b) != leaving) return {Blocked::pinch_at, at};
      // Leave along an edge of the fan or into the triangle that holds the direction.
      int next_vertex = -1, next_face = -1;
      const auto v = static_cast<std::size_t>(at);
      for (std::size_t f = fan_begin_[v]; f < fan_begin_[v + 1] && next_vertex < 0 && next_face < 0; ++f) {
        const Triangle& t = triangles_[static_cast<std::size_t>(fan_[f])];
        const int j = t.vertex[0] == at ? 0 : t.vertex[1] == at ? 1 : 2;
        const int p1 = t.vertex[ccw(j)], p2 = t.vertex[cw(j)];
        const int o1 = orientation(at_point(at), at_point(p1), b), o2 = orientation(at_point(at), at_point(p2), b);
        if (o1 == 0 && dot(at_point(p1) - at_point(at), direction) > 0) next_vertex = p1;
        else if (o2 == 0 && dot(at_point(p2) - at_point(at), direction) > 0) next_vertex = p2;
        else if (o1 > 0 && o2 < 0) next_face = fan_[f];
      }
      came_from = at;
      at = -1;
      if (next_vertex >= 0) {  // along an edge of the fan; the wedge says it is free
        if (on_segment_before(at_point(came_from), at_point(next_vertex))) return {};
        at = next_vertex;
        arrived = true;
        continue;
      }
      if (next_face < 0 || !triangles_[static_cast<std::size_t>(next_face)].free)
        return {Blocked::enters_at, came_from};
      face = next_face;
      continue;
    }
    const Triangle& t = triangles_[static_cast<std::size_t>(face)];
    if (!t.free) return {Blocked::enters};
    // The segment runs on from where it entered (or from a, inside) to a vertex on its line or
    // across the exit edge; b is in the closed triangle when it comes no later than that.
    const int side[3] = {orientation(a, b, at_point(t.vertex[0])), orientation(a, b, at_point(t.vertex[1])),
                         orientation(a, b, at_point(t.vertex[2]))};
    for (int i = 0; i < 3 && at < 0; ++i) {
      const int v = t.vertex[i];
      if (v != came_from && side[i] == 0 && ahead(at_point(v))) at = v;
    }
    if (at >= 0) {
      if (dot(at_point(at) - a, direction) >= dot(direction, direction)) return {};  // b before (or at) the vertex
      arrived = true;
      continue;
    }
    int exit_edge = -1;
    for (int i = 0; i < 3; ++i)
      if (side[ccw(i)] < 0 && side[cw(i)] > 0) exit_edge = i;
    if (exit_edge < 0) return {Blocked::lost};  // cannot happen
    if (orientation(at_point(t.vertex[ccw(exit_edge)]), at_point(t.vertex[cw(exit_edge)]), b) >= 0)
      return {};  // b before the exit
    if (t.is_constrained(exit_edge)) return {Blocked::crosses};
    face = t.neighbour[exit_edge];
    if (face < 0) return {Blocked::enters};
    came_from = -1;
  }
  return {Blocked::lost};
}

std::optional<std::string> IntegerTriangulation::why_blocked(const IntegerPoint& a, const Location& from,
                                                             const IntegerPoint& b) const {
  const Blocked blocked = walk(a, from, b);
  const auto at = [&] { return to_text(points_[static_cast<std::size_t>(blocked.vertex)]); };
  switch (blocked.reason) {
    case Blocked::none: return std::nullopt;
    case Blocked::point_blocked: return std::string("the point is blocked");
    case Blocked::start_outside: return std::string("the start is outside the free space");
    case Blocked::starts_inside: return std::string("starts inside a C-obstacle");
    case Blocked::frame: return std::string("leaves the free space at the frame");
    case Blocked::enters: return std::string("enters a C-obstacle");
    case Blocked::enters_at: return "enters a C-obstacle at " + at();
    case Blocked::pinch_at: return "passes through the pinch point " + at() + " (zero-width passage)";
    case Blocked::crosses: return std::string("crosses into a C-obstacle");
    case Blocked::lost: break;
  }
  return std::string("lost its way in the triangulation");  // cannot happen
}

bool IntegerTriangulation::path_free(const std::vector<IntegerPoint>& path, const std::vector<Location>& where) const {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (path[i] == path[i + 1] || where[i].type == Location::outside)
      return !why_path_blocked(path, where);  // the general case
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!segment_free(path[i], where[i], path[i + 1])) return false;
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    if (where[i].type != Location::vertex || static_cast<std::size_t>(where[i].index) >= space_vertices_) continue;
    const auto v = static_cast<std::size_t>(where[i].index);
    if (is_pinch(v) && wedge(v, path[i - 1] - path[i]) != wedge(v, path[i + 1] - path[i])) return false;
  }
  return true;
}

std::optional<std::string> IntegerTriangulation::why_path_blocked(const std::vector<IntegerPoint>& given,
                                                                  const std::vector<Location>& given_where) const {
  // A zero-length step carries no motion and has no direction to turn by.
  std::vector<IntegerPoint> path;
  std::vector<Location> where;
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (!path.empty() && path.back() == given[i]) continue;
    path.push_back(given[i]);
    where.push_back(i < given_where.size() && given_where[i].type != Location::outside ? given_where[i]
                                                                                       : locate(given[i]));
  }
  if (path.size() == 1) return why_blocked(path[0], where[0], path[0]);
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (auto why = why_blocked(path[i], where[i], path[i + 1]))
      return "segment " + std::to_string(i) + " " + to_text(path[i]) + "-" + to_text(path[i + 1]) + ": " + *why;
  // Turning at a pinch point: back into the wedge the path came from, never across.
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    if (where[i].type != Location::vertex || static_cast<std::size_t>(where[i].index) >= space_vertices_) continue;
    const auto v = static_cast<std::size_t>(where[i].index);
    if (is_pinch(v) && wedge(v, path[i - 1] - path[i]) != wedge(v, path[i + 1] - path[i]))
      return "turns at the pinch point " + to_text(path[i]) + " into another free wedge";
  }
  return std::nullopt;
}

}  // namespace polyplan::detail
