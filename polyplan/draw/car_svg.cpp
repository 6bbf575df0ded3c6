#include <polyplan/draw/car_svg.hpp>

#include <polyplan/car/car_motion.hpp>
#include <polyplan/draw/steering_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan {
namespace {

// At most this many bodies in one strobe.
constexpr std::size_t kMostBodiesPerPath = 80;

std::vector<std::vector<svg::Point2>> body_at(const Robot& robot, const CarPose& pose) {
  return placed_robot(robot, pose.x, pose.y, pose.theta);
}

svg::Box2 view_of(const World& world, const std::vector<PlanReport<CarState>>& reports) {
  if (world.bounds)
    return {to_double(world.bounds->xmin), to_double(world.bounds->ymin), to_double(world.bounds->xmax),
            to_double(world.bounds->ymax)};
  svg::BoxAround box;
  for (const PolygonWithHoles& o : world.obstacles)
    for (const ExactPoint& p : o.outer) box.add(to_double(p.x), to_double(p.y));
  for (const ExactPoint& p : query_points(world)) box.add(to_double(p.x), to_double(p.y));
  for (const auto& report : reports)
    for (const CarState& s : report.path)
      for (const auto& ring : body_at(world.robot, s.pose))
        for (const svg::Point2& p : ring) box.add(p.x, p.y);
  return box.box_or({0, 0, 1, 1});
}

// Poses along a path every `spacing` driven, each with the gear it is driven in.
std::vector<std::pair<CarPose, int>> strobe(const std::vector<CarState>& path, double radius, double spacing) {
  std::vector<std::pair<CarPose, int>> out;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const SteeringSegment& s = path[i].arrival;
    const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(s.length / spacing)));
    for (std::size_t k = 0; k < steps; ++k)
      out.push_back(
          {drive(path[i - 1].pose, s, radius, s.length * static_cast<double>(k) / static_cast<double>(steps)), s.gear});
  }
  return out;
}

// An edge's motion: the segment its end arrived by (hybrid A*, car-rrt), or for poses that
// arrive by none (a sampling planner's tree or roadmap) the car's shortest curve between them.
void draw_edge(svg::Drawing& d, const CarState& from, const CarState& to, const CarSteering& steering,
               const svg::Style& style) {
  if (to.arrival.length > 0) {
    d.polyline(segment_track(from.pose, to.arrival, steering.turning_radius), style);
    return;
  }
  CarPose at = from.pose;
  for (const SteeringSegment& segment : shortest_car_path(steering, from.pose, to.pose).segments) {
    d.polyline(segment_track(at, segment, steering.turning_radius), style);
    at = drive(at, segment, steering.turning_radius, segment.length);
  }
}

void draw_tree(svg::Drawing& d, const PlanGraph<CarState>& graph, const CarSteering& steering) {
  const svg::Style style{"none", theme::roadmap, 0.6, 0.45, 1.0, ""};
  for (const auto& [u, v] : graph.edges) draw_edge(d, graph.vertices[u], graph.vertices[v], steering, style);
  if (!graph.edges.empty())
    d.legend(graph.kind + " (" + std::to_string(graph.vertices.size()) + " poses)", style, svg::Swatch::line);
}

}  // namespace

svg::Drawing draw_plan(const World& world, const std::vector<PlanReport<CarState>>& reports,
                       const std::vector<std::string>& labels) {
  const CarSteering steering = world.robot.car.value_or(CarSteering{});
  const double radius = steering.turning_radius;
  const svg::Box2 box = view_of(world, reports);
  svg::Drawing d(box);
  draw_surroundings(d, world);
  for (const auto& report : reports)
    if (report.recording.graph) {
      draw_tree(d, *report.recording.graph, steering);
      break;
    }
  const double diagonal = std::hypot(box.xmax - box.xmin, box.ymax - box.ymin);
  bool forward_shown = false, reverse_shown = false;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto& path = reports[i].path;
    if (path.empty()) continue;
    if (!world.robot.is_point()) {
      double spacing = std::max(radius / 2, diagonal / 60);
      auto bodies = strobe(path, radius, spacing);
      while (bodies.size() > kMostBodiesPerPath) bodies = strobe(path, radius, spacing *= 1.5);
      for (const auto& [pose, gear] : bodies) {
        const char* colour = gear > 0 ? theme::car_forward : theme::car_reverse;
        d.polygon(body_at(world.robot, pose), svg::filled(colour, 0.10, colour, 0.7));
      }
      for (const CarPose& end : {path.front().pose, path.back().pose})
        d.polygon(body_at(world.robot, end), svg::filled(theme::start_to_goal(end == path.front().pose ? 0 : 1), 0.5,
                                                         theme::start_to_goal(end == path.front().pose ? 0 : 1), 1.6));
    }
    for (std::size_t k = 1; k < path.size(); ++k) {
      const SteeringSegment& s = path[k].arrival;
      const svg::Style style{"none", s.gear > 0 ? theme::car_forward : theme::car_reverse, 2.5, 1.0, 1.0, ""};
      d.polyline(segment_track(path[k - 1].pose, s, radius), style);
      bool& shown = s.gear > 0 ? forward_shown : reverse_shown;
      if (!shown) {
        const std::string label = i < labels.size()     ? labels[i]
                                  : reports.size() == 1 ? "path"
                                                        : "path " + std::to_string(i);
        d.legend(label + (s.gear > 0 ? ", forward" : ", reverse"), style, svg::Swatch::line);
      }
      shown = true;
    }
  }
  const double arrow = std::max(radius / 2, diagonal / 40);
  const svg::Style start_style{"none", theme::start, 2.5, 1.0, 1.0, ""},
      goal_style{"none", theme::goal, 2.5, 1.0, 1.0, ""};
  for (const Query& q : world.queries) {
    const CarPose start{to_double(q.start.x), to_double(q.start.y), q.start_theta.value_or(0) * M_PI / 180};
    const CarPose goal{to_double(q.goal.x), to_double(q.goal.y), q.goal_theta.value_or(0) * M_PI / 180};
    d.polyline(pose_arrow(start, arrow), start_style);
    d.polyline(pose_arrow(goal, arrow), goal_style);
  }
  if (!world.queries.empty()) {
    d.legend("start pose", start_style, svg::Swatch::line);
    d.legend("goal pose", goal_style, svg::Swatch::line);
  }
  return d;
}

}  // namespace polyplan
