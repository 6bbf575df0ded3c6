#include <polyplan/draw/pose_svg.hpp>

#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polyplan {
namespace {

// At most this many robots in one strobe: enough to see the motion, few enough to see through.
constexpr std::size_t kMostRobotsPerPath = 90;

// A pose for the eye: position, angle (radians, unwrapped along the path) and how far along the
// path it is (translation length plus the robot's radius times the angle turned).
struct Sample {
  double x, y, angle, progress;
};

// The path's poses, and poses between them every `spacing` units of translation or `degrees` of
// turn; angles as the poses name them (unwrapped along the path: 350° to 10° goes on to 370°).
std::vector<Sample> samples(const std::vector<Pose>& path, double radius, double spacing, double degrees) {
  std::vector<Sample> out;
  if (path.empty()) return out;
  Sample at{to_double(path[0].position.x), to_double(path[0].position.y), path[0].degrees * pi / 180, 0};
  out.push_back(at);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double x = to_double(path[i].position.x), y = to_double(path[i].position.y);
    const double turn = (path[i].degrees - path[i - 1].degrees) * pi / 180;
    const double length = std::hypot(x - at.x, y - at.y);
    const double move = turn != 0 ? std::abs(turn) / (degrees * pi / 180) : length / spacing;
    const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(move)));
    const Sample from = at;
    for (std::size_t k = 1; k <= steps; ++k) {
      const double f = static_cast<double>(k) / static_cast<double>(steps);
      // The angle from the poses' own, not summed turn by turn: a path back to 0° ends at 0° exactly.
      const double angle = (path[i - 1].degrees + (path[i].degrees - path[i - 1].degrees) * f) * pi / 180;
      at = {from.x + (x - from.x) * f, from.y + (y - from.y) * f, angle,
            from.progress + (length + radius * std::abs(turn)) * f};
      out.push_back(at);
    }
  }
  return out;
}

std::vector<std::vector<svg::Point2>> robot_at(const Robot& robot, const Sample& s) {
  return placed_robot(robot, s.x, s.y, s.angle);
}

svg::Box2 world_box(const World& world, const std::vector<std::vector<Sample>>& tracks, const Robot& robot) {
  if (world.bounds)
    return {to_double(world.bounds->xmin), to_double(world.bounds->ymin), to_double(world.bounds->xmax),
            to_double(world.bounds->ymax)};
  svg::BoxAround box;
  for (const PolygonWithHoles& o : world.obstacles)
    for (const ExactPoint& p : o.outer) box.add(to_double(p.x), to_double(p.y));
  for (const Query& q : world.queries) {
    box.add(to_double(q.start.x), to_double(q.start.y));
    box.add(to_double(q.goal.x), to_double(q.goal.y));
  }
  for (const auto& track : tracks)
    for (const Sample& s : track)
      for (const auto& ring : robot_at(robot, s))
        for (const svg::Point2& p : ring) box.add(p.x, p.y);
  return box.box_or({0, 0, 1, 1});
}

std::string degrees_label(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g°", radians * 180 / pi);
  return text;
}

}  // namespace

svg::Drawing draw_plan(const World& world, const std::vector<PlanReport<Pose>>& reports,
                       const std::vector<std::string>& labels) {
  const double radius = robot_radius(world.robot);
  std::vector<std::vector<Sample>> tracks;
  for (const auto& report : reports)
    tracks.push_back(samples(report.path, radius, 1, 360));  // corners only, for the box
  const svg::Box2 box = world_box(world, tracks, world.robot);
  const double width = box.xmax - box.xmin, height = box.ymax - box.ymin;
  // The orientation panel sits right of the world, in world units, half the world's height.
  const svg::Box2 panel{box.xmax + 0.1 * width, box.ymin + 0.25 * height, box.xmax + 0.55 * width,
                        box.ymin + 0.75 * height};
  svg::Drawing d({box.xmin, box.ymin, panel.xmax + 0.1 * width, box.ymax}, 1100);  // room for the angle labels
  draw_surroundings(d, world);

  // Strobe spacing: about the robot's radius (or a fortieth of the world), coarser when a path
  // would need more than kMostRobotsPerPath robots.
  const double diagonal = std::hypot(width, height);
  double lowest = 1e300, highest = -1e300;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto& path = reports[i].path;
    if (path.empty()) continue;
    double spacing = std::max(radius, diagonal / 40), degrees = 10;
    std::vector<Sample> track = samples(path, radius, spacing, degrees);
    for (int coarser = 0; track.size() > kMostRobotsPerPath && coarser < 20; ++coarser) {
      spacing *= 1.5;
      degrees *= 1.5;
      track = samples(path, radius, spacing, degrees);
    }
    const double total = std::max(track.back().progress, 1e-300);
    if (!world.robot.is_point())
      for (std::size_t k = 0; k < track.size(); ++k) {
        const double t = track[k].progress / total;
        const bool end = k == 0 || k + 1 == track.size();
        d.polygon(robot_at(world.robot, track[k]),
                  svg::filled(theme::start_to_goal(t), end ? 0.55 : 0.12, theme::start_to_goal(t), end ? 1.6 : 0.8));
      }
    std::vector<svg::Point2> line;
    std::vector<svg::Point2> turns;
    for (std::size_t k = 0; k < path.size(); ++k) {
      line.push_back({to_double(path[k].position.x), to_double(path[k].position.y)});
      if (k > 0 && !(path[k].rotation == path[k - 1].rotation)) turns.push_back(line.back());
    }
    const std::string label = i < labels.size()     ? labels[i]
                              : reports.size() == 1 ? "path"
                                                    : "path " + std::to_string(i);
    const svg::Style track_style{"none", theme::path_colour(i), 2.0, 1.0, 1.0, ""};
    d.polyline(line, track_style);
    d.legend(label + " (reference point)", track_style, svg::Swatch::line);
    if (!turns.empty()) {
      const svg::Style turn_style = svg::filled("#fff", 1.0, theme::path_colour(i), 2.0);
      d.points(turns, 4.0, turn_style);
      if (i == 0) d.legend("turns on the spot", turn_style, svg::Swatch::dot);
    }
    for (const Sample& s : track) {
      lowest = std::min(lowest, s.angle);
      highest = std::max(highest, s.angle);
    }
    tracks[i] = std::move(track);
  }
  if (!world.robot.is_point() && lowest <= highest) {
    d.legend("robot at start", svg::filled(theme::start_to_goal(0), 0.55, theme::start_to_goal(0), 1.6));
    d.legend("robot at goal", svg::filled(theme::start_to_goal(1), 0.55, theme::start_to_goal(1), 1.6));
  }

  // The panel: orientation (up) against progress along the path (right); a turn is a vertical step.
  if (lowest <= highest) {
    const double low = lowest == highest ? lowest - pi / 18 : lowest,
                 high = lowest == highest ? highest + pi / 18 : highest;
    const svg::Style frame{"#fff", theme::ink, 1.0, 1.0, 1.0, ""};
    d.polygon(
        {{{panel.xmin, panel.ymin}, {panel.xmax, panel.ymin}, {panel.xmax, panel.ymax}, {panel.xmin, panel.ymax}}},
        frame);
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      if (tracks[i].empty()) continue;
      const double total = std::max(tracks[i].back().progress, 1e-300);
      std::vector<svg::Point2> curve;
      for (const Sample& s : tracks[i])
        curve.push_back({panel.xmin + (panel.xmax - panel.xmin) * s.progress / total,
                         panel.ymin + (panel.ymax - panel.ymin) * (s.angle - low) / (high - low)});
      d.polyline(curve, svg::Style{"none", theme::path_colour(i), 2.0, 1.0, 1.0, ""});
    }
    const double line = 14 / d.scale();  // one text line, in world units
    d.text({panel.xmin, panel.ymax + 0.6 * line}, "orientation along the path", 13);
    d.text({panel.xmax + 0.3 * line, panel.ymax - 0.8 * line}, degrees_label(high), 12);
    d.text({panel.xmax + 0.3 * line, panel.ymin}, degrees_label(low), 12);
    d.text({panel.xmin, panel.ymin - 1.2 * line}, "start", 12);
    d.text({panel.xmax - 2.2 * line, panel.ymin - 1.2 * line}, "goal", 12);
  }

  std::vector<svg::Point2> starts, goals;
  for (const Query& q : world.queries) {
    starts.push_back({to_double(q.start.x), to_double(q.start.y)});
    goals.push_back({to_double(q.goal.x), to_double(q.goal.y)});
  }
  d.points(starts, 5.0, svg::filled(theme::start, 1.0, "#fff", 1.5));
  d.points(goals, 5.0, svg::filled(theme::goal, 1.0, "#fff", 1.5));
  if (!starts.empty()) {
    d.legend("start", svg::filled(theme::start, 1.0, "#fff", 1.5), svg::Swatch::dot);
    d.legend("goal", svg::filled(theme::goal, 1.0, "#fff", 1.5), svg::Swatch::dot);
  }
  return d;
}

}  // namespace polyplan
