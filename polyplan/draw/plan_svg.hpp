#pragma once
// Roadmaps and search traces in pictures (on top of geometry/cspace_svg.hpp's world and C-space).
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/search/roadmap.hpp>

#include <string>
#include <vector>

namespace polyplan {

// The roadmap's edges among its first `vertex_count` vertices (later ones are query slots), thin
// and translucent so the path on top stays readable, and its vertices as dots.
void draw_roadmap(svg::Drawing& drawing, const Roadmap& roadmap, std::size_t vertex_count);

// Points such as the vertices a search expanded, as small dots with a legend entry.
void draw_points(svg::Drawing& drawing, const std::vector<ExactPoint>& points, const std::string& label);

}  // namespace polyplan
