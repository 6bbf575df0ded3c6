// IntegerTriangulation::from_grid: the free space of a MovingAI map read off its cells. At a grid
// point the four cells around it decide everything: a unit edge along a grid line is a boundary
// edge when the two cells beside it differ, a point is a free-space vertex when its boundary edges
// (two or four) do not run straight through it, and the free side of each edge is the free cell.
// The boundary runs between vertices are the constraints of a constrained Delaunay triangulation
// over CGAL's Epick kernel: its predicates are exact on these integer (double) coordinates, and no
// construction is used. A triangle is free when the cell holding its centroid is.
#include <polyplan/free_space/detail/integer_triangulation.hpp>

#include <polyplan/io/movingai_map.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <unordered_map>

namespace polyplan::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

struct Cells {
  const GridMap& map;
  bool blocked(std::int64_t x, std::int64_t y) const {
    return x < 0 || y < 0 || x >= map.width || y >= map.height ||
           map.is_blocked(static_cast<int>(x), static_cast<int>(y));
  }
  // The boundary edges leaving grid point (x, y), counter-clockwise from +x (+x, +y, -x, -y; the
  // left of +x is the +y side): the cells beside each, and which one lies on the left.
  std::vector<IntegerTriangulation::Parts::WedgeEdge> edges_at(std::int64_t x, std::int64_t y) const {
    const bool nw = blocked(x - 1, y - 1), ne = blocked(x, y - 1), sw = blocked(x - 1, y), se = blocked(x, y);
    std::vector<IntegerTriangulation::Parts::WedgeEdge> edges;
    if (ne != se) edges.push_back({{1, 0}, !se});
    if (sw != se) edges.push_back({{0, 1}, !sw});
    if (nw != sw) edges.push_back({{-1, 0}, !nw});
    if (nw != ne) edges.push_back({{0, -1}, !ne});
    return edges;
  }
  static bool is_vertex(const std::vector<IntegerTriangulation::Parts::WedgeEdge>& edges) {
    return edges.size() == 4 || (edges.size() == 2 && edges[0].direction.x * edges[1].direction.y !=
                                                          edges[0].direction.y * edges[1].direction.x);
  }
};

}  // namespace

IntegerTriangulation IntegerTriangulation::from_grid(const GridMap& map) {
  const Cells cells{map};
  Parts parts;
  std::unordered_map<std::int64_t, int> vertex_at;  // key y * (width + 1) + x
  const std::int64_t row = map.width + 1;
  for (std::int64_t y = 0; y <= map.height; ++y)
    for (std::int64_t x = 0; x <= map.width; ++x) {
      auto edges = cells.edges_at(x, y);
      if (!Cells::is_vertex(edges)) continue;
      vertex_at.emplace(y * row + x, static_cast<int>(parts.points.size()));
      parts.points.push_back({x, y});
      parts.wedges.push_back(std::move(edges));
    }
  parts.space_vertices = parts.points.size();
  // Constraints: the boundary runs along each grid line, cut at every vertex.
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  auto trace = [&](bool horizontal) {
    const std::int64_t lines = horizontal ? map.height : map.width, length = horizontal ? map.width : map.height;
    for (std::int64_t line = 0; line <= lines; ++line) {
      int open = -1;  // the vertex the current run started at
      for (std::int64_t along = 0; along <= length; ++along) {
        const std::int64_t x = horizontal ? along : line, y = horizontal ? line : along;
        const auto v = vertex_at.find(y * row + x);
        if (v == vertex_at.end()) continue;
        if (open >= 0) runs.emplace_back(static_cast<std::size_t>(open), static_cast<std::size_t>(v->second));
        // A run leaves this vertex forwards when the unit edge after it is a boundary edge.
        const bool forward = along < length && (horizontal ? cells.blocked(x, y - 1) != cells.blocked(x, y)
                                                           : cells.blocked(x - 1, y) != cells.blocked(x, y));
        open = forward ? v->second : -1;
      }
    }
  };
  trace(true);
  trace(false);
  if (parts.points.size() < 3) return assemble(parts);

  std::vector<K::Point_2> points;
  for (const IntegerPoint& p : parts.points) points.emplace_back(static_cast<double>(p.x), static_cast<double>(p.y));
  CDT cdt;
  cdt.insert_constraints(points.begin(), points.end(), runs.begin(), runs.end());
  if (cdt.dimension() < 2) return assemble(parts);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    v->info() =
        vertex_at.at(static_cast<std::int64_t>(v->point().y()) * row + static_cast<std::int64_t>(v->point().x()));
  std::unordered_map<const void*, int> face_index;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    face_index.emplace(&*f, static_cast<int>(face_index.size()));
  parts.triangles.resize(face_index.size());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    Parts::Triangle& t = parts.triangles[static_cast<std::size_t>(face_index.at(&*f))];
    std::int64_t sx = 0, sy = 0;  // three times the centroid
    for (int i = 0; i < 3; ++i) {
      t.vertex[i] = f->vertex(i)->info();
      const auto n = f->neighbor(i);
      t.neighbour[i] = cdt.is_infinite(n) ? -1 : face_index.at(&*n);
      t.constrained[i] = cdt.is_constrained({f, i});
      sx += parts.points[static_cast<std::size_t>(t.vertex[i])].x;
      sy += parts.points[static_cast<std::size_t>(t.vertex[i])].y;
    }
    // The centroid is inside the triangle, which no boundary crosses: on a grid line it lies
    // between two cells of the same kind, so either one tells.
    t.free = !cells.blocked(sx / 3, sy / 3);
    t.component = -1;
  }
  // Free components: free triangles joined across unconstrained edges.
  int components = 0;
  for (std::size_t start = 0; start < parts.triangles.size(); ++start) {
    if (!parts.triangles[start].free || parts.triangles[start].component >= 0) continue;
    std::vector<std::size_t> stack{start};
    parts.triangles[start].component = components;
    while (!stack.empty()) {
      const Parts::Triangle& t = parts.triangles[stack.back()];
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (t.constrained[i] || t.neighbour[i] < 0) continue;
        Parts::Triangle& next = parts.triangles[static_cast<std::size_t>(t.neighbour[i])];
        if (!next.free || next.component >= 0) continue;
        next.component = components;
        stack.push_back(static_cast<std::size_t>(t.neighbour[i]));
      }
    }
    ++components;
  }
  return assemble(parts);
}

}  // namespace polyplan::detail
