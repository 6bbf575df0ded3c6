#pragma once
// Pictures of worlds and their C-spaces (draw/svg.hpp does the drawing; this file decides what a
// world looks like, in draw/theme.hpp's colours). Exact coordinates are rounded to double only
// here, for the eye.
#include <polyplan/draw/svg.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/geometry/cspace.hpp>

#include <string>
#include <vector>

namespace polyplan {

// Where a picture puts an exact point: its coordinates rounded to doubles (a picture's, never a
// decision's).
svg::Point2 svg_point(const ExactPoint& p);

// The world's bounds, or else the box around the obstacles, the C-obstacles, the starts and goals
// and the robot at the first start ({0, 0, 1, 1} when there is nothing at all), cut to twice the
// queries' extent round them.
svg::Box2 view_box(const World& world, const CSpace& cspace);
// The same without a C-space: a world with discs or walls has none (World::round_features).
svg::Box2 view_box(const World& world);

// The bounds (a box or a disc), the obstacles (with holes), the discs and the walls, a legend entry
// each: the world without its robot.
void draw_surroundings(svg::Drawing& drawing, const World& world);

// The robot's parts placed with its reference point at (x, y), turned by `radians`: the rings a
// strobe draws (rotating robots, cars).
std::vector<std::vector<svg::Point2>> placed_robot(const Robot& robot, double x, double y, double radians);

// The world as its file describes it: bounds, obstacles (with holes), the robot placed at the
// first start, and the starts and goals; a legend entry each.
void draw_world(svg::Drawing& drawing, const World& world);

// The bounds (a box or a circle) as a dark line, with a legend entry.
void draw_bounds(svg::Drawing& drawing, const World& world);

// What a C-space picture draws over the C-obstacles: the obstacles, discs and walls, the robot at
// the first start, the starts and goals; a legend entry each.
void draw_world_over_cspace(svg::Drawing& drawing, const World& world);

// The C-space picture's styles, for the pictures of round worlds' C-spaces too
// (draw/round_cspace_svg.hpp): where the robot would leave the bounds, and the C-obstacles.
const svg::Style& walls_style();
const svg::Style& cobstacle_style();

// In this order, each with a legend entry: the free components (pale fills, one tint per component
// when there are several, holes shown; left out with FreeSpace::unfilled, when something drawn
// before shows the free space already), the bounds, the walls (when the robot is not a point),
// the C-obstacles, the obstacles, the robot at the first start, the starts and goals.
enum class FreeSpace { filled, unfilled };
void draw_cspace(svg::Drawing& drawing, const CSpace& cspace, FreeSpace free_space = FreeSpace::filled);

// The path as a line with its vertices as small dots (or, when given, the `turns`: where a path
// drawn along arcs changes piece); nothing for an empty path.
void draw_path(svg::Drawing& drawing, const std::vector<ExactPoint>& path, const std::string& label,
               const std::string& colour = theme::path_colour(0), const std::vector<ExactPoint>& turns = {});

// The C-space picture (and a path on top, if given) written to `file`.
void write_cspace_svg(const CSpace& cspace, const std::string& file, const std::vector<ExactPoint>* path = nullptr);

}  // namespace polyplan
