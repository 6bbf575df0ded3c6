#pragma once
// The picture of a round world's C-space (geometry/round_cspace.hpp) with arcs drawn as arcs. SVG
// draws the set within r of a shape exactly: the shape filled and stroked 2r wide with round joins
// and caps (a disc: a <circle> of the grown radius; a grown wall: its polyline stroked 2r wide).
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/round_cspace.hpp>

namespace polyplan {

// In draw_cspace's order and with its legends (draw/world_svg.hpp): the free space's region (the
// box or disc the reference point keeps to, pale, the C-obstacles over it), the bounds, where the
// robot would leave them, the C-obstacles, and the world over them.
// Without `fill_free`, the free space's region is left out (cells drawn over it show it).
void draw_round_cspace(svg::Drawing& drawing, const World& world, const RoundCSpace& space, bool fill_free = true);

// The picture in the world's view (draw/world_svg.hpp view_box).
svg::Drawing round_cspace_picture(const World& world, const RoundCSpace& space);

}  // namespace polyplan
