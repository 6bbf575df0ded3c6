#include <polyplan/io/wkt_reader.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/WKT.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cctype>
#include <fstream>
#include <sstream>

namespace polyplan {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

template <typename Polygon2>
Ring ring_from(const Polygon2& polygon) {
  Ring ring;
  for (const auto& p : polygon.vertices()) ring.push_back({Rational(p.x()), Rational(p.y())});
  return ring;
}

bool has_text(const std::string& s) {
  for (char c : s)
    if (!std::isspace(static_cast<unsigned char>(c))) return true;
  return false;
}

}  // namespace

std::vector<PolygonWithHoles> read_wkt_obstacles(const std::string& wkt_path, const std::string& from_file) {
  const std::string prefix = from_file + ": obstacles_wkt \"" + wkt_path + "\": ";
  std::ifstream in(wkt_path);
  if (!in) throw InputError(prefix + "cannot open file");
  std::ostringstream content;
  content << in.rdbuf();
  const std::string text = content.str();

  std::istringstream lines(text);
  std::string line;
  std::size_t line_number = 0;
  std::vector<PolygonWithHoles> obstacles;
  auto add = [&](const CGAL::Polygon_with_holes_2<Epick>& polygon) {
    PolygonWithHoles obstacle{ring_from(polygon.outer_boundary()), {}};
    for (auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h) obstacle.holes.push_back(ring_from(*h));
    obstacles.push_back(std::move(obstacle));
  };
  while (std::getline(lines, line)) {
    ++line_number;
    if (!has_text(line)) continue;
    const std::string where = prefix + "line " + std::to_string(line_number) + ": ";
    // CGAL's read_WKT() loops forever on a line it does not know, so the type is dispatched here
    // and only the two polygon readers are called, each on its own line.
    std::string type;
    for (char c : line) {
      if (c == '(' || std::isspace(static_cast<unsigned char>(c))) {
        if (!type.empty()) break;
        continue;
      }
      type.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
    std::istringstream one(line);
    bool ok = false;
    if (type == "POLYGON") {
      CGAL::Polygon_with_holes_2<Epick> polygon;
      ok = CGAL::IO::read_polygon_WKT(one, polygon) && !polygon.outer_boundary().is_empty();
      if (ok) add(polygon);
    } else if (type == "MULTIPOLYGON") {
      std::vector<CGAL::Polygon_with_holes_2<Epick>> polygons;
      ok = CGAL::IO::read_multi_polygon_WKT(one, polygons) && !polygons.empty();
      if (ok)
        for (const auto& polygon : polygons) add(polygon);
    } else {
      throw InputError(where + "cannot read WKT: expected POLYGON or MULTIPOLYGON, got \"" + type + "\"");
    }
    if (!ok) throw InputError(where + "cannot read WKT: malformed " + type);
  }
  if (obstacles.empty()) throw InputError(prefix + "cannot read WKT: the file holds no POLYGON or MULTIPOLYGON");
  return obstacles;
}

}  // namespace polyplan
