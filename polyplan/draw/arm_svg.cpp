#include <polyplan/draw/arm_svg.hpp>

#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/angles.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {
namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

// Screen sizes in pixels.
constexpr double kPanelPx = 520;     // the workspace's larger side, and the C-space panel's side
constexpr double kTitleBandPx = 46;  // above the panels: the title and the panels' names
constexpr double kTickBandPx = 40;   // below the C-space panel: θ1's tick labels and name
constexpr double kPanelGapPx = 78;   // between the panels: θ2's tick labels and name
constexpr double kRightPadPx = 10;

// Timing of the animation.
constexpr double kSecondsPerRadian = 1;
constexpr double kFewestSeconds = 2, kMostSeconds = 60;
constexpr double kRestAtStartSeconds = 0.5, kRestAtGoalSeconds = 1;

// The end effector's path keeps at most this many vertices of the motion (the C-space path all).
constexpr std::size_t kMostTraceVertices = 2000;
// Configurations marked as where the moving arm will be, for placing the legend.
constexpr std::size_t kMostSweepMarks = 200;
// The planner's graph, evenly spread over its lists: at most this many edges traced in the
// workspace and drawn on the C-space panel, and vertices drawn as dots on each; the workspace's
// traces take a point every kGraphTraceStep of an edge's largest joint turn, a coarser step when
// they would take more than kMostGraphTracePoints points together.
constexpr std::size_t kMostWorkspaceGraphEdges = 3000;
constexpr std::size_t kMostPanelGraphEdges = 20000;
constexpr std::size_t kMostGraphVertices = 3000;
constexpr std::size_t kMostGraphTracePoints = 40000;
constexpr double kGraphTraceStep = 5 / kDegreesPerRadian;
// A two-joint report with a graph but no cells of its own (the sampling planners) gets a C-space
// panel of this many cells per axis, each checked at its centre.
constexpr std::size_t kCheckedCSpaceCells = 180;

// Colours (draw/theme.hpp): blocked configurations in the obstacles' colour, free ones in the
// free-space tint.
constexpr const char* kHatchId = "polyplan-not-evaluated";

using Points = std::vector<svg::Point2>;

using svg::filled;

svg::Style stroked(const std::string& stroke, double stroke_px, const std::string& dash = {}) {
  svg::Style s;
  s.stroke = stroke;
  s.stroke_px = stroke_px;
  s.dash = dash;
  return s;
}

svg::Point2 point(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }

// Evenly spaced indices into a sequence of `size`, at most `most` of them (at least 2), the first
// and the last always among them.
std::vector<std::size_t> spread_indices(std::size_t size, std::size_t most) {
  most = std::max<std::size_t>(most, 2);
  std::vector<std::size_t> out;
  if (size == 0) return out;
  const std::size_t count = std::min(size, most);
  if (count == 1) return {0};
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    out.push_back(static_cast<std::size_t>(
        std::llround(static_cast<double>(k) * static_cast<double>(size - 1) / static_cast<double>(count - 1))));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Checking the picture

void check_picture(const ArmPlanPicture& picture) {
  if (!picture.problem) throw std::invalid_argument("arm picture: no problem given");
  const Arm& arm = picture.problem->arm;
  for (std::size_t k = 0; k < picture.motion.size(); ++k) {
    if (picture.motion[k].size() != arm.joints()) {
      throw std::invalid_argument("arm picture: motion[" + std::to_string(k) + "] has " +
                                  std::to_string(picture.motion[k].size()) + " joint angles, the arm has " +
                                  std::to_string(arm.joints()) + " joints");
    }
    for (double angle : picture.motion[k]) {
      if (!std::isfinite(angle)) {
        throw std::invalid_argument("arm picture: motion[" + std::to_string(k) + "] has a non-finite angle");
      }
    }
  }
  if (picture.graph) {
    const PlanGraph<JointAngles>& graph = *picture.graph;
    for (std::size_t k = 0; k < graph.vertices.size(); ++k) {
      if (graph.vertices[k].size() != arm.joints()) {
        throw std::invalid_argument("arm picture: graph vertex " + std::to_string(k) + " has " +
                                    std::to_string(graph.vertices[k].size()) + " joint angles, the arm has " +
                                    std::to_string(arm.joints()) + " joints");
      }
      for (double angle : graph.vertices[k]) {
        if (!std::isfinite(angle)) {
          throw std::invalid_argument("arm picture: graph vertex " + std::to_string(k) + " has a non-finite angle");
        }
      }
    }
    for (std::size_t k = 0; k < graph.edges.size(); ++k) {
      const auto& [u, v] = graph.edges[k];
      if (u >= graph.vertices.size() || v >= graph.vertices.size()) {
        throw std::invalid_argument("arm picture: graph edge " + std::to_string(k) + " joins vertices " +
                                    std::to_string(u) + " and " + std::to_string(v) + " of " +
                                    std::to_string(graph.vertices.size()));
      }
    }
  }
  if (picture.target &&
      !(picture.target->point.allFinite() && std::isfinite(picture.target->orientation.value_or(0)))) {
    throw std::invalid_argument("arm picture: the goal point (or its orientation) is not finite");
  }
  if (picture.cspace) {
    if (arm.joints() != 2) {
      throw std::invalid_argument("arm picture: a C-space image needs an arm of 2 joints, this one has " +
                                  std::to_string(arm.joints()));
    }
    const std::size_t n = picture.cspace->columns;
    if (n == 0 || picture.cspace->rows != n || picture.cspace->states.size() != n * n) {
      throw std::invalid_argument("arm picture: C-space image of " + std::to_string(n) + " cells per axis has " +
                                  std::to_string(picture.cspace->rows) + " rows and " +
                                  std::to_string(picture.cspace->states.size()) + " states, not n·n");
    }
    for (std::uint8_t s : picture.cspace->states) {
      if (s > CellGrid::blocked) {
        throw std::invalid_argument("arm picture: C-space image has a cell of state " + std::to_string(s) +
                                    " (0 not evaluated, 1 free, 2 blocked)");
      }
    }
  }
}

bool shows_graph(const ArmPlanPicture& picture) {
  return picture.graph && !(picture.graph->vertices.empty() && picture.graph->edges.empty());
}

// ---------------------------------------------------------------------------------------------
// Angles along the motion

// The motion with every joint's angle made continuous: each step is the signed short way round
// (as the planners interpolate), so 6.2 → 0.1 becomes 6.2 → 6.383…. SMIL interpolates keyframe
// values linearly: wrapped values would swing the arm the long way round at every 2π → 0.
std::vector<JointAngles> unwrapped(const std::vector<JointAngles>& motion) {
  std::vector<JointAngles> out;
  out.reserve(motion.size());
  for (std::size_t k = 0; k < motion.size(); ++k) {
    if (k == 0) {
      out.push_back(motion[0]);
      continue;
    }
    JointAngles next = out.back();
    for (std::size_t j = 0; j < next.size(); ++j) next[j] += signed_angle_difference(motion[k - 1][j], motion[k][j]);
    out.push_back(std::move(next));
  }
  return out;
}

// Path length up to each configuration: the sum of every joint's turn.
std::vector<double> cumulative_turn(const std::vector<JointAngles>& unwrapped_motion) {
  std::vector<double> out(unwrapped_motion.size(), 0.0);
  for (std::size_t k = 1; k < unwrapped_motion.size(); ++k) {
    double step = 0;
    for (std::size_t j = 0; j < unwrapped_motion[k].size(); ++j) {
      step += std::abs(unwrapped_motion[k][j] - unwrapped_motion[k - 1][j]);
    }
    out[k] = out[k - 1] + step;
  }
  return out;
}

// When each keyframe is shown: the configurations kept (first and last repeated for the rests at
// both ends) and their times as fractions of the period, in proportion to the path length so
// that the joints turn at a steady speed.
struct Timeline {
  std::vector<std::size_t> frames;  // indices into the motion
  std::vector<double> key_times;    // 0 first, 1 last, never decreasing
  double seconds = 0;               // the period, rests included
};

Timeline timeline(const std::vector<double>& turn, double seconds, std::size_t max_keyframes) {
  Timeline t;
  if (turn.empty()) return t;
  const double length = turn.back();
  const double moving = seconds > 0 && std::isfinite(seconds)
                            ? seconds
                            : std::clamp(kSecondsPerRadian * length, kFewestSeconds, kMostSeconds);
  t.seconds = kRestAtStartSeconds + moving + kRestAtGoalSeconds;
  const std::vector<std::size_t> kept = spread_indices(turn.size(), max_keyframes);
  const double last = static_cast<double>(turn.size() - 1);
  t.frames.push_back(kept.front());
  t.key_times.push_back(0);
  for (std::size_t i : kept) {
    // A motion that does not move (start = goal) still advances through its keyframes.
    const double progress = length > 0 ? turn[i] / length : (last > 0 ? static_cast<double>(i) / last : 0);
    t.frames.push_back(i);
    t.key_times.push_back((kRestAtStartSeconds + moving * progress) / t.seconds);
  }
  t.frames.push_back(kept.back());
  t.key_times.push_back(1);
  return t;
}

std::string seconds_attribute(double seconds) { return "dur=\"" + svg::format_number(seconds) + "s\""; }

std::string key_times_attribute(const std::vector<double>& key_times) {
  std::string out = "keyTimes=\"";
  for (std::size_t i = 0; i < key_times.size(); ++i) {
    if (i > 0) out += ';';
    out += svg::format_number(key_times[i]);
  }
  return out + '"';
}

// ---------------------------------------------------------------------------------------------
// Layout: the workspace on the left, the C-space panel (if any) on the right, in one drawing whose
// units are the workspace's; the panel maps [0, 2π]² onto a square as high as the workspace is
// large.

struct Layout {
  svg::Box2 workspace{};
  bool has_panel = false;
  double panel_x = 0, panel_y = 0, panel_side = 0;
  double px = 1;  // drawing units per screen pixel
  svg::Box2 whole{};
  double width_px = 800;

  svg::Point2 on_panel(double theta1, double theta2) const {
    return {panel_x + theta1 / two_pi * panel_side, panel_y + theta2 / two_pi * panel_side};
  }
};

svg::Box2 workspace_box(const ArmPlanPicture& picture) {
  const ArmProblem& problem = *picture.problem;
  double r = problem.arm.reach();
  if (!(r > 0) || !std::isfinite(r)) r = 1;
  svg::BoxAround box({-r, -r, r, r});
  for (const PolygonWithHoles& o : problem.obstacles)
    for (const ExactPoint& p : o.outer) box.add(to_double(p.x), to_double(p.y));
  for (const Eigen::Vector2d& p : problem.points) box.add(p.x(), p.y());
  if (picture.target) box.add(picture.target->point.x(), picture.target->point.y());  // an unreachable one too
  return box.box_or({});
}

Layout layout(const ArmPlanPicture& picture) {
  Layout l;
  l.workspace = workspace_box(picture);
  const svg::Box2& w = l.workspace;
  const double larger = std::max(w.xmax - w.xmin, w.ymax - w.ymin);
  l.px = larger / kPanelPx;
  l.has_panel = picture.cspace.has_value();
  l.whole = {w.xmin, w.ymin, w.xmax, w.ymax + kTitleBandPx * l.px};
  if (l.has_panel) {
    l.panel_side = larger;
    l.panel_x = w.xmax + kPanelGapPx * l.px;
    l.panel_y = w.ymin;
    l.whole.xmax = l.panel_x + l.panel_side + kRightPadPx * l.px;
    l.whole.ymin = w.ymin - kTickBandPx * l.px;
    l.whole.ymax = std::max(w.ymax, l.panel_y + l.panel_side) + kTitleBandPx * l.px;
  }
  // svg::Drawing adds a margin of 4% of the larger side on each side: choose the width that keeps
  // kPanelPx pixels for the workspace's larger side.
  const double margin = 0.04 * std::max(l.whole.xmax - l.whole.xmin, l.whole.ymax - l.whole.ymin);
  l.width_px = (l.whole.xmax - l.whole.xmin + 2 * margin) / l.px;
  return l;
}

// About how wide a label is, in pixels: UTF-8 code points at 0.6 em each.
double text_width_px(const std::string& text, double size_px) {
  std::size_t glyphs = 0;
  for (unsigned char c : text) glyphs += (c & 0xC0) != 0x80;
  return 0.6 * size_px * static_cast<double>(glyphs);
}

// Text centred on `at` (the writer starts text at its anchor).
void centred_text(svg::Drawing& d, const Layout& l, svg::Point2 at, const std::string& text, double size_px) {
  d.text({at.x - text_width_px(text, size_px) / 2 * l.px, at.y}, text, size_px);
}

void draw_titles(svg::Drawing& d, const Layout& l, const ArmPlanPicture& picture) {
  const std::string& title = picture.title;
  const double top = l.whole.ymax;
  if (!title.empty()) d.text({l.whole.xmin, top - 18 * l.px}, title, 15);
  const double names_y = std::max(l.workspace.ymax, l.panel_y + l.panel_side) + 8 * l.px;
  d.text({l.workspace.xmin, names_y}, picture.motion.empty() ? "workspace — no path" : "workspace", 12);
  if (l.has_panel) {
    d.text({l.panel_x, names_y},
           picture.torus ? "C-space θ1 × θ2 (a torus: opposite edges meet)" : "C-space θ1 × θ2 (intervals [0, 2π))",
           12);
  }
}

// ---------------------------------------------------------------------------------------------
// The workspace

void draw_surroundings(svg::Drawing& d, const ArmProblem& problem) {
  // The obstacles exactly as a world's are drawn (geometry/cspace_svg.hpp).
  World world;
  world.obstacles = problem.obstacles;
  draw_world(d, world);

  if (!problem.points.empty()) {
    Points dots;
    for (const Eigen::Vector2d& p : problem.points) dots.push_back(point(p));
    const svg::Style s = filled(theme::obstacle_fill, 1.0, theme::obstacle_edge, 0.8);
    d.points(dots, 3.5, s);
    d.legend("obstacle points (" + std::to_string(dots.size()) + ")", s, svg::Swatch::dot);
  }

  const double reach = problem.arm.reach();
  if (reach > 0 && std::isfinite(reach)) {
    Points circle;
    constexpr int kSides = 180;
    for (int i = 0; i < kSides; ++i) {
      const double a = two_pi * i / kSides;
      circle.push_back({reach * std::cos(a), reach * std::sin(a)});
    }
    const svg::Style s = stroked(theme::reach, 1, "5 4");
    d.polygon({circle}, s);
    d.legend("reach", s, svg::Swatch::line);
  }
}

// Where the hand should go: a ring with a cross on the point, and an arrow along the last link's
// orientation there when the goal has one (as long as the last link, or 30 px at least).
void draw_target(svg::Drawing& d, const Layout& l, const Arm& arm, const std::optional<WorkspaceGoal>& target) {
  if (!target) return;
  const svg::Point2 at = point(target->point);
  const double arm_px = 7 * l.px;
  const svg::Style line = stroked(theme::arm_goal_edge, 1.8);
  d.begin_group("class=\"goal-point\"");
  d.points({at}, 7, stroked(theme::arm_goal_edge, 1.8));
  d.segments({{{at.x - arm_px, at.y}, {at.x + arm_px, at.y}}, {{at.x, at.y - arm_px}, {at.x, at.y + arm_px}}}, line);
  if (target->orientation) {
    const double length = std::max(arm.links.back(), 30 * l.px), head = 8 * l.px, a = *target->orientation;
    const svg::Point2 tip{at.x + length * std::cos(a), at.y + length * std::sin(a)};
    const auto barb = [&](double turn) {
      return svg::Point2{tip.x - head * std::cos(a + turn), tip.y - head * std::sin(a + turn)};
    };
    d.segments({{at, tip}, {tip, barb(0.45)}, {tip, barb(-0.45)}}, line);
  }
  d.end_group();
  d.legend(target->orientation ? "goal point and orientation (the hand's target)" : "goal point (the hand's target)",
           line, svg::Swatch::line);
}

void draw_base(svg::Drawing& d) {
  const svg::Style s = filled(theme::ink, 1.0, "#fff", 1.5);
  d.points({{0, 0}}, 5.5, s);
  d.legend("base", s, svg::Swatch::dot);
}

// How one configuration of the arm is drawn: rectangles (links of some width) or thick lines.
struct LinkLook {
  svg::Style body;
  svg::Style joint;  // the dots on the joints
};

LinkLook link_look(const Arm& arm, const std::string& colour, const std::string& edge, double opacity) {
  LinkLook look;
  look.body = arm.link_width > 0 ? filled(colour, 1.0, edge, 1.2) : stroked(colour, 5);
  look.body.opacity = opacity;
  look.joint = filled("#fff", 1.0, edge, 1.5);
  look.joint.opacity = opacity;
  return look;
}

void draw_link(svg::Drawing& d, const Arm& arm, const std::vector<Eigen::Vector2d>& joints, std::size_t link,
               const LinkLook& look) {
  Points outline;
  for (const Eigen::Vector2d& p : link_outline(arm, joints, link)) outline.push_back(point(p));
  if (outline.size() >= 3) {
    d.polygon({outline}, look.body);
  } else {
    d.polyline(outline, look.body);
  }
}

void draw_configuration(svg::Drawing& d, const Arm& arm, const JointAngles& q, const LinkLook& look, bool with_joints) {
  const std::vector<Eigen::Vector2d> joints = joint_positions(arm, q);
  for (std::size_t i = 0; i < arm.joints(); ++i) draw_link(d, arm, joints, i, look);
  if (with_joints) {
    Points dots;
    for (std::size_t i = 1; i < joints.size(); ++i) dots.push_back(point(joints[i]));
    d.points(dots, 3, look.joint);
  }
}

// The end effector's path, dashed; `over_graph`: on a white halo, so that it stands out of the
// graph's traces beneath it.
void draw_tip_path(svg::Drawing& d, const Arm& arm, const std::vector<JointAngles>& motion, bool over_graph) {
  if (motion.size() < 2) return;
  Points tip;
  for (std::size_t i : spread_indices(motion.size(), kMostTraceVertices)) {
    tip.push_back(point(joint_positions(arm, motion[i]).back()));
  }
  if (over_graph) {
    svg::Style halo = stroked("#fff", 4);
    halo.opacity = 0.85;
    d.polyline(tip, halo);
  }
  const svg::Style s = stroked(theme::trace, 1.3, "2 3");
  d.polyline(tip, s);
  d.legend("end-effector path", s, svg::Swatch::line);
}

// The planner's graph looks as a polygon world's does (draw/plan_svg.cpp's draw_graph): thin faint
// edges and dots in the roadmap's colour, the dots smaller and fainter here (a tree of thousands).
svg::Style graph_edge_style() {
  svg::Style s = stroked(theme::roadmap, 0.7);
  s.opacity = 0.45;
  return s;
}

svg::Style graph_vertex_style() {
  svg::Style s = filled(theme::roadmap, 1.0, "none", 0);
  s.opacity = 0.7;
  return s;
}

// "12", or "3000 of 12000" when fewer are drawn than there are.
std::string drawn_of(std::size_t drawn, std::size_t all) {
  return drawn == all ? std::to_string(all) : std::to_string(drawn) + " of " + std::to_string(all);
}

// The graph in the workspace: each edge as the end effector's trace while every joint turns the
// short way along it, each vertex as a dot where it puts the end effector.
void draw_workspace_graph(svg::Drawing& d, const Arm& arm, const PlanGraph<JointAngles>& graph) {
  const std::vector<std::size_t> edges = spread_indices(graph.edges.size(), kMostWorkspaceGraphEdges);
  const std::vector<std::size_t> vertices = spread_indices(graph.vertices.size(), kMostGraphVertices);
  if (edges.empty() && vertices.empty()) return;
  std::vector<Eigen::Vector2d> joints;
  auto tip = [&](const JointAngles& q) {
    joint_positions_into(arm, q, joints);
    return point(joints.back());
  };

  // The largest joint turn of each edge, and the step along it that keeps the points in bounds.
  std::vector<double> turns;
  turns.reserve(edges.size());
  for (std::size_t e : edges) {
    const JointAngles& a = graph.vertices[graph.edges[e].first];
    const JointAngles& b = graph.vertices[graph.edges[e].second];
    double turn = 0;
    for (std::size_t j = 0; j < a.size(); ++j) turn = std::max(turn, angular_distance(a[j], b[j]));
    turns.push_back(turn);
  }
  const auto steps = [](double turn, double step) {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(turn / step)));
  };
  double step = kGraphTraceStep, total_turn = 0;
  std::size_t points = 0;
  for (double turn : turns) {
    points += 1 + steps(turn, step);
    total_turn += turn;
  }
  // An edge takes 1 + max(1, ⌈turn / step⌉) ≤ 2 + turn / step points: this step keeps them all
  // within kMostGraphTracePoints (and is coarser than kGraphTraceStep, as they would not be).
  static_assert(kMostGraphTracePoints > 2 * kMostWorkspaceGraphEdges);
  if (points > kMostGraphTracePoints) {
    step = total_turn / static_cast<double>(kMostGraphTracePoints - 2 * edges.size());
  }

  std::vector<std::pair<svg::Point2, svg::Point2>> traces;  // chained: one move-to per edge
  JointAngles q;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const JointAngles& a = graph.vertices[graph.edges[edges[i]].first];
    const JointAngles& b = graph.vertices[graph.edges[edges[i]].second];
    const std::size_t n = steps(turns[i], step);
    svg::Point2 from = tip(a);
    for (std::size_t k = 1; k <= n; ++k) {
      interpolate_angles_into(a, b, static_cast<double>(k) / static_cast<double>(n), q);
      const svg::Point2 to = tip(q);
      traces.push_back({from, to});
      from = to;
    }
  }
  Points dots;
  dots.reserve(vertices.size());
  for (std::size_t v : vertices) dots.push_back(tip(graph.vertices[v]));

  const svg::Style edge_style = graph_edge_style(), vertex_style = graph_vertex_style();
  d.begin_group("class=\"workspace-graph\"");
  d.segments(traces, edge_style);
  d.points(dots, 1.1, vertex_style);
  d.end_group();
  if (!edges.empty()) {
    d.legend(graph.kind + " edges (" + drawn_of(edges.size(), graph.edges.size()) + "): end-effector traces",
             edge_style, svg::Swatch::line);
  }
  if (!vertices.empty()) {
    d.legend(graph.kind + " vertices (" + drawn_of(vertices.size(), graph.vertices.size()) + ")", vertex_style,
             svg::Swatch::dot);
  }
}

// The arm at the motion's keyframes: one group per link nested in its parent's, each rotating by
// its joint's relative angle about where its joint is at the zero configuration, so the parents'
// rotations carry it along. Links are drawn at the zero configuration (all along +x); the static
// transforms put the arm at the start for viewers without animation.
void draw_moving_arm(svg::Drawing& d, const Arm& arm, const std::vector<JointAngles>& unwrapped_motion,
                     const Timeline& t) {
  const std::vector<Eigen::Vector2d> zero = joint_positions(arm, JointAngles(arm.joints(), 0.0));
  const LinkLook look = link_look(arm, theme::arm_fill, theme::arm_edge, 1.0);
  const std::string timing =
      seconds_attribute(t.seconds) + " repeatCount=\"indefinite\" " + key_times_attribute(t.key_times);
  for (std::size_t i = 0; i < arm.joints(); ++i) {
    const svg::Point2 centre = d.to_screen(point(zero[i]));
    const std::string about = " " + svg::format_number(centre.x) + " " + svg::format_number(centre.y);
    // The picture's y axis points down: a counter-clockwise world angle is a negative SVG rotation.
    auto rotation = [&](std::size_t frame) {
      return svg::format_number(-unwrapped_motion[frame][i] * kDegreesPerRadian) + about;
    };
    std::string values;
    for (std::size_t k = 0; k < t.frames.size(); ++k) {
      if (k > 0) values += ';';
      values += rotation(t.frames[k]);
    }
    d.begin_group("class=\"arm-link\" transform=\"rotate(" + rotation(t.frames.front()) + ")\"",
                  "<animateTransform attributeName=\"transform\" type=\"rotate\" " + timing + " values=\"" + values +
                      "\"/>",
                  svg::Drawing::GroupContent::moves);
    draw_link(d, arm, zero, i, look);
    if (i > 0) d.points({point(zero[i])}, 3, look.joint);
  }
  d.points({point(zero.back())}, 3.5, filled(theme::arm_edge, 1.0, "#fff", 1));  // the end effector
  for (std::size_t i = 0; i < arm.joints(); ++i) d.end_group();

  // The legend stays off where the arm will pass (what moves marks no room as taken).
  for (std::size_t k : spread_indices(t.frames.size(), kMostSweepMarks)) {
    Points line;
    for (const Eigen::Vector2d& p : joint_positions(arm, unwrapped_motion[t.frames[k]])) line.push_back(point(p));
    d.keep_clear(line);
  }
}

// ---------------------------------------------------------------------------------------------
// The C-space panel

// A vertex of the C-space path on the panel, at its moment of the animation.
struct PanelVertex {
  double theta1, theta2;  // in [0, 2π]
  double time;
};
using PanelPiece = std::vector<PanelVertex>;

// The two-joint path as pieces on the square [0, 2π]²: where it crosses a seam (θ passes 2π or
// 0) a piece ends on one edge and the next begins on the opposite one, so no line runs across the
// picture. `angles` are unwrapped (continuous); `times` go with them.
std::vector<PanelPiece> panel_pieces(const std::vector<std::array<double, 2>>& angles,
                                     const std::vector<double>& times) {
  std::vector<PanelPiece> pieces;
  if (angles.empty()) return pieces;
  // Which copy of the square the path is in, per axis: the position on the panel is angle − 2π·tile.
  std::array<double, 2> tile{std::floor(angles[0][0] / two_pi), std::floor(angles[0][1] / two_pi)};
  auto on_square = [&](const std::array<double, 2>& a, double time) {
    return PanelVertex{a[0] - two_pi * tile[0], a[1] - two_pi * tile[1], time};
  };
  pieces.push_back({on_square(angles[0], times[0])});
  for (std::size_t k = 1; k < angles.size(); ++k) {
    const std::array<double, 2>& from = angles[k - 1];
    const std::array<double, 2>& to = angles[k];
    struct Crossing {
      double s;  // where along the step, 0..1
      int axis, direction;
    };
    std::vector<Crossing> crossings;
    for (int axis = 0; axis < 2; ++axis) {
      const double step = to[axis] - from[axis];
      if (step > 0) {
        for (double edge = two_pi * (tile[axis] + 1); to[axis] > edge; edge += two_pi) {
          crossings.push_back({(edge - from[axis]) / step, axis, +1});
        }
      } else if (step < 0) {
        for (double edge = two_pi * tile[axis]; to[axis] < edge; edge -= two_pi) {
          crossings.push_back({(edge - from[axis]) / step, axis, -1});
        }
      }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
    for (const Crossing& c : crossings) {
      const std::array<double, 2> at{from[0] + c.s * (to[0] - from[0]), from[1] + c.s * (to[1] - from[1])};
      const double time = times[k - 1] + c.s * (times[k] - times[k - 1]);
      PanelVertex leaving = on_square(at, time);
      (c.axis == 0 ? leaving.theta1 : leaving.theta2) = c.direction > 0 ? two_pi : 0;  // exactly on the edge
      pieces.back().push_back(leaving);
      tile[c.axis] += c.direction;
      PanelVertex entering = on_square(at, time);
      (c.axis == 0 ? entering.theta1 : entering.theta2) = c.direction > 0 ? 0 : two_pi;
      pieces.push_back({entering});
    }
    pieces.back().push_back(on_square(to, times[k]));
  }
  return pieces;
}

std::vector<std::array<double, 2>> two_joints(const std::vector<JointAngles>& unwrapped_motion,
                                              const std::vector<std::size_t>& frames) {
  std::vector<std::array<double, 2>> out;
  out.reserve(frames.size());
  for (std::size_t i : frames) out.push_back({unwrapped_motion[i][0], unwrapped_motion[i][1]});
  return out;
}

// The graph on the panel: each edge the short way round between its ends, a straight line on the
// torus cut where it crosses a seam (as the path is), each vertex a dot; under the path.
void draw_panel_graph(svg::Drawing& d, const Layout& l, const PlanGraph<JointAngles>& graph) {
  const std::vector<std::size_t> edges = spread_indices(graph.edges.size(), kMostPanelGraphEdges);
  const std::vector<std::size_t> vertices = spread_indices(graph.vertices.size(), kMostGraphVertices);
  if (edges.empty() && vertices.empty()) return;
  std::vector<std::pair<svg::Point2, svg::Point2>> lines;
  lines.reserve(edges.size());
  const std::vector<double> no_times(2, 0.0);
  for (std::size_t e : edges) {
    const std::vector<JointAngles> ends =
        unwrapped({graph.vertices[graph.edges[e].first], graph.vertices[graph.edges[e].second]});
    for (const PanelPiece& piece : panel_pieces(two_joints(ends, {0, 1}), no_times)) {
      for (std::size_t k = 1; k < piece.size(); ++k) {
        lines.push_back(
            {l.on_panel(piece[k - 1].theta1, piece[k - 1].theta2), l.on_panel(piece[k].theta1, piece[k].theta2)});
      }
    }
  }
  Points dots;
  dots.reserve(vertices.size());
  for (std::size_t v : vertices) {
    const JointAngles& q = graph.vertices[v];
    dots.push_back(l.on_panel(normalize_angle(q[0]), normalize_angle(q[1])));
  }
  const svg::Style edge_style = graph_edge_style();
  d.begin_group("class=\"cspace-graph\"");
  d.segments(lines, edge_style);
  d.points(dots, 1.4, graph_vertex_style());
  d.end_group();
  if (!edges.empty()) {
    d.legend(graph.kind + " edges (" + drawn_of(edges.size(), graph.edges.size()) + ") in C-space", edge_style,
             svg::Swatch::line);
  }
}

// The cells as rectangles: a horizontal run of equal state is one rectangle, and so is the same
// run repeated in the rows above it; the rectangles of a state are one path (a 360 × 360 image
// stays small, and cells of one state show no seams between them).
void draw_cells(svg::Drawing& d, const Layout& l, const CellGrid& image) {
  const std::size_t n = image.columns;
  const double cell = two_pi / static_cast<double>(n);
  // Extended index e = 0..n: cell e mod n, clipped to [0, 2π], so cell 0 shows at both edges.
  auto extent = [&](std::size_t e) {
    return std::array<double, 2>{std::max(0.0, (static_cast<double>(e) - 0.5) * cell),
                                 std::min(two_pi, (static_cast<double>(e) + 0.5) * cell)};
  };
  std::array<std::size_t, 3> cells{0, 0, 0};
  for (std::uint8_t s : image.states) ++cells[s];

  struct Block {
    std::size_t begin, end;  // extended columns, inclusive
    std::uint8_t state;
    std::size_t first_row;  // extended rows first_row .. the row before it was closed
  };
  std::array<std::vector<svg::Box2>, 3> rects;  // per state
  auto close = [&](const Block& b, std::size_t last_row) {
    const svg::Point2 p = l.on_panel(extent(b.begin)[0], extent(b.first_row)[0]);
    const svg::Point2 q = l.on_panel(extent(b.end)[1], extent(last_row)[1]);
    rects[b.state].push_back({p.x, p.y, q.x, q.y});
  };
  std::vector<Block> open, next;  // ordered by begin; the runs of a row partition it
  for (std::size_t row = 0; row <= n; ++row) {
    const auto state_at = [&](std::size_t e) { return image.states[(e % n) + (row % n) * n]; };
    next.clear();
    std::size_t above = 0;  // the first open block that may continue
    std::size_t begin = 0;
    for (std::size_t e = 1; e <= n + 1; ++e) {
      if (e <= n && state_at(e) == state_at(begin)) continue;
      const Block run{begin, e - 1, state_at(begin), row};
      while (above < open.size() && open[above].begin < run.begin) close(open[above++], row - 1);
      if (above < open.size() && open[above].begin == run.begin && open[above].end == run.end &&
          open[above].state == run.state) {
        next.push_back(open[above++]);  // the same run as in the row below: the block grows
      } else {
        next.push_back(run);
      }
      begin = e;
    }
    while (above < open.size()) close(open[above++], row - 1);
    open.swap(next);
  }
  for (const Block& b : open) close(b, n);

  if (cells[CellGrid::not_evaluated] > 0) {
    // Lazy search leaves most cells unknown: hatched, so they are not mistaken for free ones.
    d.raw(std::string("<defs><pattern id=\"") + kHatchId +
          "\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" patternTransform=\"rotate(45)\">"
          "<rect width=\"6\" height=\"6\" fill=\"#fff\"/><path d=\"M0 0V6\" stroke=\"" +
          theme::not_evaluated_hatch +
          "\" stroke-width=\"1.5\"/>"
          "</pattern></defs>");
  }
  d.begin_group("class=\"cspace-cells\"");
  struct Kind {
    std::uint8_t state;
    svg::Style style;
    const char* label;
  };
  const Kind kinds[] = {
      {CellGrid::free, filled(theme::free_tints[0].fill, 1.0, "none", 0), "free"},
      {CellGrid::blocked, filled(theme::obstacle_fill, 1.0, "none", 0), "blocked"},
      {CellGrid::not_evaluated, filled(std::string("url(#") + kHatchId + ")", 1.0, "none", 0), "not evaluated"},
  };
  for (const Kind& k : kinds) {
    if (rects[k.state].empty()) continue;
    d.boxes(rects[k.state], k.style);
    svg::Style swatch = k.style;
    swatch.stroke = "#aaa";
    swatch.stroke_px = 0.75;
    d.legend(std::string(k.label) + " configurations (" + std::to_string(cells[k.state]) + " cells)", swatch,
             svg::Swatch::area);
  }
  d.end_group();
}

void draw_panel_frame(svg::Drawing& d, const Layout& l) {
  const svg::Point2 a = l.on_panel(0, 0), b = l.on_panel(two_pi, two_pi);
  d.polygon({{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}}}, stroked(theme::ink, 1));
  static const char* const kTicks[] = {"0", "π/2", "π", "3π/2", "2π"};
  const double tick = 5 * l.px, size = 12;
  std::vector<std::pair<svg::Point2, svg::Point2>> marks;
  for (int k = 0; k <= 4; ++k) {
    const double angle = k * two_pi / 4;
    const svg::Point2 x = l.on_panel(angle, 0), y = l.on_panel(0, angle);
    marks.push_back({x, {x.x, x.y - tick}});
    marks.push_back({y, {y.x - tick, y.y}});
    centred_text(d, l, {x.x, x.y - tick - 14 * l.px}, kTicks[k], size);
    d.text({y.x - tick - (4 + text_width_px(kTicks[k], size)) * l.px, y.y - 0.35 * size * l.px}, kTicks[k], size);
  }
  d.segments(marks, stroked(theme::ink, 1));
  centred_text(d, l, {(a.x + b.x) / 2, a.y - tick - 32 * l.px}, "θ1 (joint 1)", 13);
  // θ2's name between its two top tick labels, right-aligned with them.
  const svg::Point2 name = l.on_panel(0, 7 * two_pi / 8);
  d.text({name.x - tick - (4 + text_width_px("θ2", 13)) * l.px, name.y - 0.35 * 13 * l.px}, "θ2", 13);
}

// The path on the panel, split at the seams, with its start and goal, over the graph if any (on a
// white halo then); with `timeline`, a ring moves along it in step with the arm (the same period
// and keyTimes, and a jump where it crosses a seam).
void draw_panel(svg::Drawing& d, const Layout& l, const CellGrid& image, const PlanGraph<JointAngles>* graph,
                const std::vector<JointAngles>& unwrapped_motion, const Timeline* timeline) {
  draw_cells(d, l, image);
  if (graph) draw_panel_graph(d, l, *graph);
  draw_panel_frame(d, l);
  if (unwrapped_motion.empty()) return;

  std::vector<std::size_t> all(unwrapped_motion.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const std::vector<PanelPiece> pieces =
      panel_pieces(two_joints(unwrapped_motion, all), std::vector<double>(all.size(), 0.0));
  std::vector<Points> lines;
  for (const PanelPiece& piece : pieces) {
    Points& line = lines.emplace_back();
    for (const PanelVertex& v : piece) line.push_back(l.on_panel(v.theta1, v.theta2));
  }
  if (graph) {  // a white halo lifts the path off the graph
    svg::Style halo = stroked("#fff", 5.5);
    halo.opacity = 0.85;
    for (const Points& line : lines) d.polyline(line, halo);
  }
  const svg::Style path_style = stroked(theme::arm_fill, 2.5);
  d.begin_group("class=\"cspace-path\"");
  for (const Points& line : lines) d.polyline(line, path_style);
  d.end_group();
  d.legend("path in C-space", path_style, svg::Swatch::line);

  const PanelVertex& first = pieces.front().front();
  const PanelVertex& last = pieces.back().back();
  d.points({l.on_panel(first.theta1, first.theta2)}, 5, filled(theme::arm_start, 1.0, "#fff", 1.5));
  d.points({l.on_panel(last.theta1, last.theta2)}, 5, filled(theme::arm_goal, 1.0, "#fff", 1.5));

  if (!timeline) return;
  // A ring, so that the start and goal marks show through it when it rests on them.
  std::string xs, ys, times;
  for (const PanelPiece& piece : panel_pieces(two_joints(unwrapped_motion, timeline->frames), timeline->key_times)) {
    for (const PanelVertex& v : piece) {
      const svg::Point2 s = d.to_screen(l.on_panel(v.theta1, v.theta2));
      if (!xs.empty()) {
        xs += ';';
        ys += ';';
        times += ';';
      }
      xs += svg::format_number(s.x);
      ys += svg::format_number(s.y);
      times += svg::format_number(v.time);
    }
  }
  const svg::Point2 at = d.to_screen(l.on_panel(first.theta1, first.theta2));
  const std::string timing =
      seconds_attribute(timeline->seconds) + " repeatCount=\"indefinite\" keyTimes=\"" + times + "\"";
  d.raw("<circle class=\"cspace-dot\" cx=\"" + svg::format_number(at.x) + "\" cy=\"" + svg::format_number(at.y) +
        "\" r=\"7.5\" fill=\"none\" stroke=\"" + theme::arm_edge + "\" stroke-width=\"2.5\">\n" +
        "<animate attributeName=\"cx\" " + timing + " values=\"" + xs + "\"/>\n" + "<animate attributeName=\"cy\" " +
        timing + " values=\"" + ys + "\"/>\n</circle>");
  d.legend("the arm's configuration now", stroked(theme::arm_edge, 2.5), svg::Swatch::dot);
}

// ---------------------------------------------------------------------------------------------

// "1st", "2nd", "3rd", "4th", …, "11th", "12th", "13th", "21st", …
std::string ordinal(std::size_t k) {
  const std::size_t tens = k % 100, units = k % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1               ? "st"
                       : units == 2               ? "nd"
                       : units == 3               ? "rd"
                                                  : "th";
  return std::to_string(k) + suffix;
}

svg::Drawing animation_drawing(const ArmPlanPicture& picture) {
  check_picture(picture);
  const ArmProblem& problem = *picture.problem;
  const Layout l = layout(picture);
  svg::Drawing d(l.whole, l.width_px);
  draw_titles(d, l, picture);
  draw_surroundings(d, problem);
  if (shows_graph(picture)) draw_workspace_graph(d, problem.arm, *picture.graph);

  const std::vector<JointAngles> continuous = unwrapped(picture.motion);
  if (!picture.motion.empty()) {
    draw_tip_path(d, problem.arm, picture.motion, shows_graph(picture));
    const LinkLook start = link_look(problem.arm, theme::arm_start, theme::arm_start_edge, 0.35);
    const LinkLook goal = link_look(problem.arm, theme::arm_goal, theme::arm_goal_edge, 0.35);
    draw_configuration(d, problem.arm, picture.motion.front(), start, false);
    draw_configuration(d, problem.arm, picture.motion.back(), goal, false);
    d.legend("start (ghost)", start.body);
    d.legend("goal (ghost)", goal.body);
  }
  draw_target(d, l, problem.arm, picture.target);
  draw_base(d);

  const Timeline t = timeline(cumulative_turn(continuous), picture.seconds, picture.max_keyframes);
  if (!picture.motion.empty()) {
    draw_moving_arm(d, problem.arm, continuous, t);
    char period[32];
    std::snprintf(period, sizeof period, "%.1f", t.seconds);
    d.legend(std::string("arm, moving (") + period + " s loop)",
             link_look(problem.arm, theme::arm_fill, theme::arm_edge, 1).body);
  }
  if (picture.cspace) {
    draw_panel(d, l, *picture.cspace, shows_graph(picture) ? picture.graph.get() : nullptr, continuous,
               picture.motion.empty() ? nullptr : &t);
  }
  return d;
}

svg::Drawing strobe_drawing(const ArmPlanPicture& picture, std::size_t every_kth) {
  check_picture(picture);
  if (every_kth == 0) throw std::invalid_argument("arm strobe picture: every_kth must be at least 1");
  const ArmProblem& problem = *picture.problem;
  const Arm& arm = problem.arm;
  const Layout l = layout(picture);
  svg::Drawing d(l.whole, l.width_px);
  draw_titles(d, l, picture);
  draw_surroundings(d, problem);
  if (shows_graph(picture)) draw_workspace_graph(d, arm, *picture.graph);

  const std::vector<JointAngles>& motion = picture.motion;
  if (!motion.empty()) {
    draw_tip_path(d, arm, motion, shows_graph(picture));
    const std::size_t last = motion.size() - 1;
    std::size_t drawn = 0;
    // In between, translucent, so that where the arm lingers shows darker.
    for (std::size_t i = every_kth; i < last; i += every_kth) {
      const double t = static_cast<double>(i) / static_cast<double>(last);
      const std::string colour = theme::start_to_goal(t);
      d.begin_group("class=\"strobe-configuration\"");
      draw_configuration(d, arm, motion[i], link_look(arm, colour, colour, 0.45), false);
      d.end_group();
      ++drawn;
    }
    const LinkLook start = link_look(arm, theme::arm_start, theme::arm_start_edge, 1);
    const LinkLook goal = link_look(arm, theme::arm_goal, theme::arm_goal_edge, 1);
    if (last > 0) {  // a motion of one configuration is its own goal
      d.begin_group("class=\"strobe-configuration strobe-goal\"");
      draw_configuration(d, arm, motion[last], goal, true);
      d.end_group();
    }
    d.begin_group("class=\"strobe-configuration strobe-start\"");
    draw_configuration(d, arm, motion.front(), start, true);
    d.end_group();
    d.legend("start", start.body);
    d.legend("goal", goal.body);
    if (drawn > 0) {
      const std::string k = every_kth == 1 ? "every configuration" : "every " + ordinal(every_kth) + " configuration";
      d.legend(k + " (" + std::to_string(drawn) + " of " + std::to_string(motion.size()) + "), blue → red",
               link_look(arm, theme::start_to_goal(0.5), theme::start_to_goal(0.5), 0.45).body);
    }
  }
  draw_target(d, l, arm, picture.target);
  draw_base(d);
  if (picture.cspace) {
    draw_panel(d, l, *picture.cspace, shows_graph(picture) ? picture.graph.get() : nullptr, unwrapped(motion), nullptr);
  }
  return d;
}

// The C-space of a two-joint arm as the panel shows it: cell (i, j) centred on the angles
// (i·2π/n, j·2π/n), free or blocked as the collision checker says there.
CellGrid checked_cspace(const ArmProblem& problem, std::size_t n) {
  const ArmCollisionChecker checker(problem);
  CellGrid image;
  image.columns = image.rows = n;
  const double step = two_pi / static_cast<double>(n);
  image.x0 = image.y0 = -step / 2;
  image.cell_width = image.cell_height = step;
  image.states.resize(n * n);
  JointAngles q(2);
  for (std::size_t row = 0; row < n; ++row) {
    for (std::size_t column = 0; column < n; ++column) {
      q = {static_cast<double>(column) * step, static_cast<double>(row) * step};
      image.states[column + row * n] = checker.is_free(q) ? CellGrid::free : CellGrid::blocked;
    }
  }
  return image;
}

}  // namespace

svg::Drawing draw_arm_configurations(const ArmPlanPicture& picture, const std::vector<std::string>& labels) {
  check_picture(picture);
  const Arm& arm = picture.problem->arm;
  const Layout l = layout(picture);
  svg::Drawing d(l.whole, l.width_px);
  draw_titles(d, l, picture);
  draw_surroundings(d, *picture.problem);
  constexpr std::size_t named = 8;  // legend entries; the others are counted in one
  for (std::size_t i = 0; i < picture.motion.size(); ++i) {
    const LinkLook look = link_look(arm, theme::path_colour(i), theme::path_colour(i), 0.8);
    draw_configuration(d, arm, picture.motion[i], look, true);
    if (i < named) d.legend(i < labels.size() ? labels[i] : "configuration " + std::to_string(i + 1), look.body);
  }
  if (picture.motion.size() > named)
    d.legend("and " + std::to_string(picture.motion.size() - named) + " more",
             link_look(arm, theme::trace, theme::trace, 0.8).body);
  draw_target(d, l, arm, picture.target);
  draw_base(d);
  return d;
}

std::string arm_animation_svg(const ArmPlanPicture& picture) { return animation_drawing(picture).str(); }

std::string arm_strobe_svg(const ArmPlanPicture& picture, std::size_t every_kth) {
  return strobe_drawing(picture, every_kth).str();
}

svg::Drawing draw_plan(const ArmProblem& problem, const PlanReport<JointAngles>& report,
                       const ArmPictureOptions& options) {
  ArmPlanPicture picture;
  picture.problem = &problem;
  picture.title = options.title;
  picture.target = options.target;
  const double step = options.degrees_per_frame * two_pi / 360;
  for (std::size_t k = 0; k + 1 < report.path.size(); ++k) {
    const auto samples = motion_samples(report.path[k], report.path[k + 1], step);
    picture.motion.insert(picture.motion.end(), samples.begin() + (k == 0 ? 0 : 1), samples.end());
  }
  if (report.path.size() == 1) picture.motion = report.path;
  if (report.recording.cells && problem.arm.joints() == 2) picture.cspace = *report.recording.cells;
  picture.graph = report.recording.graph;
  // The graph of a planner without a grid still shows on the C-space, among the C-obstacles.
  if (shows_graph(picture) && !report.recording.cells && problem.arm.joints() == 2) {
    picture.cspace = checked_cspace(problem, kCheckedCSpaceCells);
  }
  if (report.recording.cells) picture.torus = report.recording.cells->wraps;
  if (options.kind == ArmPictureOptions::Kind::animation) return animation_drawing(picture);
  const std::size_t about_a_dozen = std::max<std::size_t>(1, picture.motion.size() / 12);
  return strobe_drawing(picture, options.every_kth ? options.every_kth : about_a_dozen);
}

void write_arm_animation_svg(const std::string& path, const ArmPlanPicture& picture) {
  animation_drawing(picture).write(path);
}

void write_arm_strobe_svg(const std::string& path, const ArmPlanPicture& picture, std::size_t every_kth) {
  strobe_drawing(picture, every_kth).write(path);
}

svg::Drawing draw_ik_study(const ArmProblem& problem, const IkRequest& request, const IkStudy& study,
                           const std::string& title) {
  ArmPlanPicture picture;
  picture.problem = &problem;
  picture.target = WorkspaceGoal{request.target, request.orientation_radians()};
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < study.answer.solutions.size(); ++i) {
    picture.motion.push_back(study.answer.solutions[i].angles);
    char label[96];
    std::snprintf(label, sizeof label, "%s %zu, error %.2g%s", study.answer.found ? "solution" : "closest", i + 1,
                  study.answer.solutions[i].error, study.free[i] ? "" : ", collides");
    labels.push_back(label);
  }
  picture.title = title;
  return draw_arm_configurations(picture, labels);
}

}  // namespace polyplan
