#pragma once
// Pictures of a planar arm's plan (draw/svg.hpp does the drawing, draw/theme.hpp gives the
// colours): the arm moving along its path as an SVG animation (SMIL only, no script, so it plays
// in any browser and a file viewer still shows a sensible picture), a "strobe" with every k-th
// configuration drawn at once (the course's arm and car planning report's figure), and for two joints the torus C-space
// θ1 × θ2 beside the workspace with the path on it (the course's graph-search homework's Figure 2); either with the
// planner's roadmap or tree drawn faint under the path. draw_plan makes either from any arm planner's report.
#include <polyplan/arm/ik_study.hpp>
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct ArmPlanPicture {
  const ArmProblem* problem = nullptr;  // the arm, its obstacles and obstacle points
  // The configurations along the path, densely, start first and goal last. Between consecutive
  // ones every joint turns the short way round (as the planners interpolate); an empty motion
  // draws the world alone, marked "no path".
  std::vector<JointAngles> motion;
  // Two joints only: the C-space grid θ1 × θ2 drawn as a second panel, with the path on it.
  // Square, cell k of an axis centred on the angle k·2π/n (so cell 0 straddles the seam, half at
  // 0 and half at 2π); the grid's x0, y0 and cell sizes are not read.
  std::optional<CellGrid> cspace;
  std::string title;  // e.g. "two_link_points.json · hard · torus · 5°"
  // How long the motion takes in the animation; 0: one second per radian of path length (the
  // sum of the joints' turns), at least 2 s and at most 60 s. The animation also rests 0.5 s at
  // the start and 1 s at the goal before it repeats.
  double seconds = 0;
  // Keyframes the animation keeps at most (the first and last always): a path of thousands of
  // configurations still gives a small file. At least 2.
  std::size_t max_keyframes = 600;
  // How the planner saw the joint angles: a torus (the C-space panel says its opposite edges
  // meet), or intervals [0, 2π) that a path never crosses 0 in (the planners' --no-torus).
  bool torus = true;
  // Optional: the planner's roadmap or tree (a report's graph, kept with QueryOptions::record),
  // drawn faint and thin under the path in theme::roadmap, as polygon worlds draw theirs. On the
  // C-space panel each edge is the short way between its ends (a straight line on the torus, cut
  // where it crosses a seam) and each vertex a dot. In the workspace each edge is the end
  // effector's trace while the joints turn along it (a point every 5° of the largest turn, fewer
  // when the traces together would pass 40000 points) and each vertex a dot at the end effector.
  // At most 3000 edges are traced in the workspace and 20000 drawn on the panel, and 3000
  // vertices drawn on each, evenly spread over the graph's lists; the legend says "tree edges (N)",
  // or "(3000 of N)" when not all are drawn. Vertices may be any finite angles.
  std::shared_ptr<const PlanGraph<JointAngles>> graph;
  // Optional: a goal in the workspace (the query's goal_point), marked where the hand should go — a
  // ring with a cross, and an arrow along the orientation when it has one — in the goal's colour.
  std::optional<WorkspaceGoal> target = std::nullopt;
};

// The workspace (obstacles, obstacle points, the reach circle, the base, the end effector's path,
// the start and goal configurations as faint ghosts) with the arm moving from start to goal, for
// ever; and the C-space panel when the picture has one, with a ring moving along the path in step
// with the arm. Without animation (rsvg-convert, print) the arm stands at the start.
// Throws std::invalid_argument when the picture is inconsistent (no problem, a configuration or
// graph vertex with the wrong number of joints or a non-finite angle, a graph edge naming no
// vertex, a C-space image for an arm that has not two joints or whose state is not n·n, a target
// that is not finite).
std::string arm_animation_svg(const ArmPlanPicture& picture);

// The workspace with configurations 0, k, 2k, … of the motion (and the goal) drawn at once, the
// colour going from blue at the start to red at the goal, start and goal solid and the others
// translucent; and the C-space panel with the path when the picture has one.
// Throws std::invalid_argument as arm_animation_svg does, and when every_kth is 0.
std::string arm_strobe_svg(const ArmPlanPicture& picture, std::size_t every_kth);

// Configurations that are not a motion (inverse kinematics' solutions) drawn at once, each in a
// colour of its own with its label (the first eight in the legend); the workspace only.
svg::Drawing draw_arm_configurations(const ArmPlanPicture& picture, const std::vector<std::string>& labels);

// An inverse-kinematics study's solutions at once (draw_arm_configurations), each labelled
// "solution 2, error 1e-13, collides" ("closest 1, ..." when none reaches), the target marked.
svg::Drawing draw_ik_study(const ArmProblem& problem, const IkRequest& request, const IkStudy& study,
                           const std::string& title);

// Any arm planner's report as a picture: the path's motions drawn densely (every joint at most
// `degrees_per_frame` between frames, as the planners interpolate: each joint the short way), the
// report's cells as the C-space panel (two joints), the panel labelled a torus unless the cells do
// not wrap (the grid's --no-torus), and the report's graph (when the query recorded one) under the path;
// a two-joint report with a graph but no cells (a sampling planner's) gets a panel of 2° cells
// checked at their centres. The animation, or the strobe of every k-th frame (k = every_kth, or
// about a dozen configurations when 0).
struct ArmPictureOptions {
  enum class Kind { animation, strobe };
  Kind kind = Kind::animation;
  std::string title;
  std::size_t every_kth = 0;
  double degrees_per_frame = 1;
  std::optional<WorkspaceGoal> target =
      std::nullopt;  // the query's goal point, when it has one: marked (ArmPlanPicture::target)
};
svg::Drawing draw_plan(const ArmProblem& problem, const PlanReport<JointAngles>& report,
                       const ArmPictureOptions& options);

// The same, written to `path`; std::runtime_error naming the file when it cannot be written.
void write_arm_animation_svg(const std::string& path, const ArmPlanPicture& picture);
void write_arm_strobe_svg(const std::string& path, const ArmPlanPicture& picture, std::size_t every_kth);

}  // namespace polyplan
