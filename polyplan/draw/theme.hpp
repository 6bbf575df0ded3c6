#pragma once
// polyplan's one colour theme: every picture takes its colours from here, by role, so that an
// obstacle, a start or a path looks the same in a world, a C-space, a plan and an arm animation.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace polyplan::theme {

// What is there: obstacles solid blue-grey; C-obstacles translucent orange (the obstacles sit on
// top of them); where the robot would leave the bounds grey; the bounds a dark line.
inline constexpr const char* obstacle_fill = "#51606f";
inline constexpr const char* obstacle_edge = "#2b3440";
inline constexpr const char* cobstacle_fill = "#f4a259";
inline constexpr const char* cobstacle_edge = "#c8691c";
inline constexpr const char* walls_fill = "#8c8c8c";
inline constexpr const char* bounds = "#222";
inline constexpr const char* ink = "#222";  // text, frames, ticks

// The free space in pale tints, one per component so that disconnected regions are told apart;
// the first is the free space's (and the free cells') colour.
struct Tint {
  const char* fill;
  const char* edge;
};
inline constexpr Tint free_tints[] = {{"#e3f1e5", "#9cc7a4"}, {"#e2ebf7", "#9db4d6"}, {"#f6eedb", "#d1b682"},
                                      {"#efe4f3", "#bf9ccb"}, {"#dff1f0", "#8cc2bd"}, {"#f3efe0", "#c2b88c"}};

// Grid cells of a raster: blocked lavender (the obstacles drawn over them stay visible), grid
// vertices green.
inline constexpr const char* blocked_cell_fill = "#b9b2c9";
inline constexpr const char* blocked_cell_edge = "#8d84a3";
inline constexpr const char* cell_vertex = "#6aa77a";
inline constexpr const char* not_evaluated_hatch = "#c8c8c8";
// A path's clearance disc at its bottleneck: translucent violet.
inline constexpr const char* clearance_fill = "#b39ddb";
inline constexpr const char* clearance_edge = "#5e35b1";
// The walls of a decomposition (dashed), between its pale cells.
inline constexpr const char* wall_line = "#5b7f95";

// A value per cell (a distance field) as a heat map, low to high in viridis's steps (dark purple
// next to the obstacles, yellow far from them), and the ridge cells (a GVD) near-black over it.
inline constexpr const char* heat[] = {"#440154", "#46327e", "#365c8d", "#277f8e",
                                       "#1fa187", "#4ac16d", "#a0da39", "#fde725"};
inline constexpr std::size_t heat_steps = sizeof heat / sizeof heat[0];
inline constexpr const char* ridge_cell = "#111111";

// Queries: starts green, goals red; a robot at its start in translucent green.
inline constexpr const char* start = "#2ca02c";
inline constexpr const char* goal = "#d62728";
inline constexpr const char* robot_fill = "#2ca02c";
inline constexpr const char* robot_edge = "#1b6e1b";

// Plans: roadmap (or tree) blue and thin, expanded vertices amber, paths in the palette's order.
inline constexpr const char* roadmap = "#2a7ab0";
inline constexpr const char* separating_edge = "#b0452a";  // a visibility graph's separating bitangents
inline constexpr const char* other_edge = "#9a9a9a";       // and visibility-full's other edges
inline constexpr const char* expanded_fill = "#f2b701";
inline constexpr const char* expanded_edge = "#7a5c00";
inline constexpr const char* path_palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                               "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
inline constexpr std::size_t path_palette_size = sizeof path_palette / sizeof path_palette[0];
inline const char* path_colour(std::size_t i) { return path_palette[i % path_palette_size]; }
// What planners mark beside the path (plan/plan_report.hpp PlanMark), in turn: hit points, leave
// points, the m-line, sensed regions, ...
inline constexpr const char* mark_palette[] = {"#e6550d", "#3182bd", "#756bb1", "#31a354", "#636363"};
inline constexpr std::size_t mark_palette_size = sizeof mark_palette / sizeof mark_palette[0];

// Cars: forward driving blue, reverse orange, turning circles dashed grey.
inline constexpr const char* car_forward = "#1f77b4";
inline constexpr const char* car_reverse = "#ff7f0e";
inline constexpr const char* turning_circle = "#9aa5b1";

// Arms: the moving arm orange; its start configuration blue and its goal red (a strobe ramps
// between them); the reach circle, the end effector's trace and the base in greys.
inline constexpr const char* arm_fill = "#f28e2b";
inline constexpr const char* arm_edge = "#8a4a0f";
inline constexpr const char* arm_start = "#1f77b4";
inline constexpr const char* arm_start_edge = "#14507d";
inline constexpr const char* arm_goal = "#d62728";
inline constexpr const char* arm_goal_edge = "#8f1a1b";
inline constexpr const char* reach = "#9a9a9a";
inline constexpr const char* trace = "#555";

// From arm_start at t = 0 to arm_goal at t = 1, channel by channel ("#rrggbb"): the colour of a
// strobe's configurations along a motion.
inline std::string start_to_goal(double t) {
  const auto channel = [](const char* colour, int i) {
    return static_cast<int>(std::strtol(std::string(colour + 1 + 2 * i, 2).c_str(), nullptr, 16));
  };
  const auto mix = [&](int i) {
    const int a = channel(arm_start, i), b = channel(arm_goal, i);
    return static_cast<int>(std::lround(a + (b - a) * std::clamp(t, 0.0, 1.0)));
  };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", mix(0), mix(1), mix(2));
  return buffer;
}

}  // namespace polyplan::theme
