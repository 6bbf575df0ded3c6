#include <polyplan/draw/steering_svg.hpp>

#include <polyplan/draw/theme.hpp>

#include <cmath>
#include <vector>

namespace polyplan {
namespace {

svg::Style line(const char* colour, double px) { return svg::Style{"none", colour, px, 1.0, 1.0, ""}; }

std::vector<svg::Point2> circle(double cx, double cy, double r) {
  std::vector<svg::Point2> ring;
  for (int i = 0; i <= 96; ++i) ring.push_back({cx + r * std::cos(i * M_PI / 48), cy + r * std::sin(i * M_PI / 48)});
  return ring;
}

svg::Box2 view_of(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius) {
  svg::BoxAround box;
  for (const CarPose& p : {from, to}) {
    box.add(p.x - 2 * radius, p.y - 2 * radius);
    box.add(p.x + 2 * radius, p.y + 2 * radius);
  }
  for (int i = 0; i <= 200; ++i) {
    const CarPose q = pose_along(path, from, radius, path.length() * i / 200);
    box.add(q.x, q.y);
  }
  return box.box_or({0, 0, 1, 1});
}

void draw_segments(svg::Drawing& drawing, const SteeringPath& path, const CarPose& from, double radius) {
  CarPose at = from;
  bool forward_shown = false, reverse_shown = false;
  for (const SteeringSegment& s : path.segments) {
    const svg::Style style = line(s.gear > 0 ? theme::car_forward : theme::car_reverse, 2.5);
    drawing.polyline(segment_track(at, s, radius), style);
    bool& shown = s.gear > 0 ? forward_shown : reverse_shown;
    if (!shown) drawing.legend(s.gear > 0 ? "forward" : "reverse", style, svg::Swatch::line);
    shown = true;
    at = drive(at, s, radius, s.length);
  }
}

}  // namespace

std::vector<svg::Point2> pose_arrow(const CarPose& p, double length) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  const svg::Point2 tip{p.x + length * c, p.y + length * s};
  const double head = length / 4;
  return {{p.x, p.y},
          tip,
          {tip.x - head * (c - s / 2), tip.y - head * (s + c / 2)},
          tip,
          {tip.x - head * (c + s / 2), tip.y - head * (s - c / 2)}};
}

std::vector<svg::Point2> segment_track(const CarPose& from, const SteeringSegment& segment, double radius) {
  const int steps = segment.steer == Steer::straight
                        ? 1
                        : std::max(2, static_cast<int>(std::ceil(segment.length / radius / (M_PI / 90))));
  std::vector<svg::Point2> track;
  for (int i = 0; i <= steps; ++i) {
    const CarPose q = drive(from, segment, radius, segment.length * i / steps);
    track.push_back({q.x, q.y});
  }
  return track;
}

svg::Drawing draw_steering(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius,
                           const std::string& title) {
  svg::Drawing drawing(view_of(path, from, to, radius));
  const svg::Style circles{"none", theme::turning_circle, 1, 1, 1, "4 3"};
  for (const CarPose& p : {from, to})
    for (int side : {1, -1})  // left centre: radius to the left of the heading
      drawing.polyline(circle(p.x - side * radius * std::sin(p.theta), p.y + side * radius * std::cos(p.theta), radius),
                       circles);
  drawing.legend("turning circles", circles, svg::Swatch::line);
  // The poses under the path, so that a short first segment shows over the start's arrow.
  drawing.polyline(pose_arrow(from, radius), line(theme::start, 2.5));
  drawing.legend("start", line(theme::start, 2.5), svg::Swatch::line);
  drawing.polyline(pose_arrow(to, radius), line(theme::goal, 2.5));
  drawing.legend("goal", line(theme::goal, 2.5), svg::Swatch::line);
  draw_segments(drawing, path, from, radius);
  const svg::Box2 v = drawing.view();
  drawing.text({v.xmin + 0.02 * (v.xmax - v.xmin), v.ymax - 0.04 * (v.ymax - v.ymin)}, title, 14);
  return drawing;
}

}  // namespace polyplan
