#pragma once
// The picture of a robot's drive through a map it discovered (polyplan replan): the true map, what
// the robot knew at the end (blocked cells it saw dark, blocked cells it never saw pale, free cells
// it saw tinted), the traversed path and the last path it planned. Drawn as the map file reads:
// row 0 at the top.
#include <polyplan/draw/svg.hpp>
#include <polyplan/incremental/discovering_robot.hpp>

#include <string>

namespace polyplan {

// "polyplan replan MAP (ALGORITHM)": the title the program and Python give.
std::string replan_title(const ReplanResult& result);

// `title` is written at the top.
svg::Drawing draw_replan(const ReplanResult& result, const std::string& title);

// The same drive as an animation (SMIL, looping): one frame per move, `seconds_per_move` each,
// the robot moving from cell to cell and each cell appearing, free or blocked, when it is first
// sensed; the blocked cells never seen stay pale throughout.
svg::Drawing draw_replan_animation(const ReplanResult& result, const std::string& title,
                                   double seconds_per_move = 0.15);

}  // namespace polyplan
