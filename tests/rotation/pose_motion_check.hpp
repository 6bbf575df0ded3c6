#pragma once
// An independent re-check of a rotating robot's pose path, by dense sampling in doubles.
//
// The rotation planner certifies its motions exactly (docs/design.md "Exactness"). A test that asked
// the same exact code whether the path is free would share its mistakes, so this check shares
// none of it: no CGAL, no C-space, only the robot placed in doubles at closely spaced poses along
// each motion and the area it shares with each obstacle. Sampling can miss an overlap thinner
// than a step, so it is a test oracle that catches wrong certificates, never a certificate.
//
// The area is measured by clipping each obstacle to convex pieces of the robot
// (Sutherland–Hodgman), not by a general polygon overlay: planners' paths slide along walls, and
// an overlay must decide whether polygons that touch cross, which rounding decides either way.
// Boost.Geometry 1.74 then counted a whole robot part (or a whole obstacle) as the overlap, for
// about one in ten touching placements in rotation_seed004.json. Clipping takes no such decision:
// rounding moves the area by rounding only.
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/world.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan::test {

namespace pose_check_detail {

inline constexpr double pi = 3.14159265358979323846;

// Contact is free, but a robot touching an obstacle in doubles overlaps it by rounding (~1e-15 of
// the world's size); an overlap counts when its area exceeds this fraction of the squared diagonal,
// and a vertex leaves the bounds when it is outside by more than this fraction of the diagonal.
inline constexpr double relative_slack = 1e-9;

struct Vec {
  double x, y;
};
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
inline double cross(Vec a, Vec b) { return a.x * b.y - a.y * b.x; }

using Loop = std::vector<Vec>;  // a closed polygon, first vertex not repeated

inline double signed_area(const Loop& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) twice += cross(loop[i], loop[(i + 1) % loop.size()]);
  return twice / 2;
}

inline Loop loop_of(const Ring& ring) {
  Loop loop;
  for (const ExactPoint& p : ring) loop.push_back({to_double(p.x), to_double(p.y)});
  return loop;
}

inline Loop oriented(Loop loop, bool counter_clockwise) {
  if ((signed_area(loop) > 0) != counter_clockwise) std::reverse(loop.begin(), loop.end());
  return loop;
}

// The signed area of `subject` inside the convex counter-clockwise `clip`. Clipped to each edge's
// half-plane, a closed loop keeps its winding number inside and gets 0 outside (it may run back and
// forth along the edge, which adds no area), so the result is the area of the intersection for any
// subject, convex or not; a clockwise subject (a hole) gives it negative.
inline double clipped_area(Loop subject, const Loop& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const Vec a = clip[e], edge = clip[(e + 1) % clip.size()] - a;
    Loop kept;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Vec p = subject[i], q = subject[(i + 1) % subject.size()];
      const double sp = cross(edge, p - a), sq = cross(edge, q - a);
      if (sp >= 0) kept.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double t = sp / (sp - sq);
        kept.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      }
    }
    subject = std::move(kept);
  }
  return signed_area(subject);
}

// A counter-clockwise simple polygon as convex counter-clockwise pieces: itself when convex,
// else triangles cut off as ears.
inline std::vector<Loop> convex_pieces(Loop loop) {
  const auto turn = [&](std::size_t i) {
    const std::size_t n = loop.size();
    return cross(loop[i] - loop[(i + n - 1) % n], loop[(i + 1) % n] - loop[i]);
  };
  bool convex = true;
  for (std::size_t i = 0; i < loop.size(); ++i) convex = convex && turn(i) >= 0;
  if (convex) return {loop};
  std::vector<Loop> pieces;
  while (loop.size() > 3) {
    const std::size_t n = loop.size();
    std::optional<std::size_t> ear, flat;
    for (std::size_t i = 0; i < n && !ear; ++i) {
      if (turn(i) == 0) flat = i;
      if (turn(i) <= 0) continue;
      const Vec a = loop[(i + n - 1) % n], b = loop[i], c = loop[(i + 1) % n];
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j)
        if (j != i && j != (i + 1) % n && j != (i + n - 1) % n)
          empty = !(cross(b - a, loop[j] - a) >= 0 && cross(c - b, loop[j] - b) >= 0 && cross(a - c, loop[j] - c) >= 0);
      if (empty) ear = i;
    }
    if (!ear && !flat) throw std::invalid_argument("pose_motion_check: a robot part is not a simple polygon");
    const std::size_t cut = ear ? *ear : *flat;  // a flat vertex goes without changing the shape
    if (ear) pieces.push_back({loop[(cut + n - 1) % n], loop[cut], loop[(cut + 1) % n]});
    loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(cut));
  }
  pieces.push_back(loop);
  return pieces;
}

struct Box {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  void add(Vec p) {
    xmin = std::min(xmin, p.x), ymin = std::min(ymin, p.y), xmax = std::max(xmax, p.x), ymax = std::max(ymax, p.y);
  }
  bool meets(const Box& o) const { return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax; }
};

inline Box box_of(const Loop& loop) {
  Box box;
  for (const Vec& p : loop) box.add(p);
  return box;
}

struct Obstacle {
  std::vector<Loop> boundary;  // the outer loop counter-clockwise, the holes clockwise
  Box box;
  std::string name;
};

inline double distance_to_segment(Vec p, Vec a, Vec b) {
  const Vec d = b - a;
  const double length2 = d.x * d.x + d.y * d.y;
  const double t = length2 > 0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * d.x, p.y - a.y - t * d.y);
}

// Whether `p` is inside the obstacle (outer loop but no hole) by more than `slack` from its boundary.
inline bool deep_inside(Vec p, const Obstacle& o, double slack) {
  int crossings = 0;
  for (const Loop& loop : o.boundary)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec a = loop[i], b = loop[(i + 1) % loop.size()];
      if (distance_to_segment(p, a, b) <= slack) return false;
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) ++crossings;
    }
  return crossings % 2 == 1;
}

// A sampled configuration: the reference point and the angle in degrees.
struct Sample {
  double x, y, degrees;
};

// The world in doubles, converted once for all samples.
struct SampledWorld {
  std::vector<std::vector<Loop>> parts;  // convex pieces of each robot part, robot frame; none: a point robot
  std::vector<Obstacle> obstacles;
  std::optional<Box> bounds;
  double diagonal = 0;  // of the bounds, or else of the obstacles and the path's positions

  SampledWorld(const World& world, const std::vector<Pose>& path) {
    for (const Ring& part : world.robot.parts) parts.push_back(convex_pieces(oriented(loop_of(part), true)));
    Box extent;
    for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
      Obstacle o;
      o.boundary.push_back(oriented(loop_of(world.obstacles[i].outer), true));
      for (const Ring& hole : world.obstacles[i].holes) o.boundary.push_back(oriented(loop_of(hole), false));
      o.box = box_of(o.boundary.front());
      o.name = i < world.obstacle_names.size() ? world.obstacle_names[i] : "obstacles[" + std::to_string(i) + "]";
      for (const Vec corner : {Vec{o.box.xmin, o.box.ymin}, Vec{o.box.xmax, o.box.ymax}}) extent.add(corner);
      obstacles.push_back(std::move(o));
    }
    for (const Pose& pose : path) extent.add({to_double(pose.position.x), to_double(pose.position.y)});
    if (world.bounds) {
      const Bounds& b = *world.bounds;
      bounds = Box{to_double(b.xmin), to_double(b.ymin), to_double(b.xmax), to_double(b.ymax)};
      extent = *bounds;
    }
    diagonal = std::hypot(extent.xmax - extent.xmin, extent.ymax - extent.ymin);
  }

  double length_slack() const { return relative_slack * diagonal; }
  double area_slack() const { return relative_slack * diagonal * diagonal; }

  bool outside_bounds(Vec p) const {
    return bounds && (p.x < bounds->xmin - length_slack() || p.x > bounds->xmax + length_slack() ||
                      p.y < bounds->ymin - length_slack() || p.y > bounds->ymax + length_slack());
  }
};

inline std::string describe(const Sample& s) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g°)", s.x, s.y, s.degrees);
  return text;
}

inline Loop placed(const Loop& piece, const Sample& s) {
  const double c = std::cos(s.degrees * pi / 180), sn = std::sin(s.degrees * pi / 180);
  Loop out;  // a rotation keeps the orientation and the convexity
  for (const Vec& p : piece) out.push_back({s.x + c * p.x - sn * p.y, s.y + sn * p.x + c * p.y});
  return out;
}

// What the robot at `s` overlaps beyond rounding, or nullopt when it is free.
inline std::optional<std::string> overlap_at(const SampledWorld& w, const Sample& s) {
  if (w.parts.empty()) {  // a point robot: only its position matters, and it has no area to overlap
    const Vec p{s.x, s.y};
    if (w.outside_bounds(p)) return std::string("the point robot leaves the bounds");
    for (const Obstacle& o : w.obstacles)
      if (deep_inside(p, o, w.length_slack())) return "the point robot is inside " + o.name;
    return std::nullopt;
  }
  for (std::size_t k = 0; k < w.parts.size(); ++k) {
    std::vector<double> shared(w.obstacles.size(), 0.0);
    for (const Loop& piece : w.parts[k]) {
      const Loop at = placed(piece, s);
      for (const Vec& p : at)
        if (w.outside_bounds(p)) return "robot part " + std::to_string(k) + " leaves the bounds";
      const Box box = box_of(at);
      for (std::size_t i = 0; i < w.obstacles.size(); ++i)
        if (box.meets(w.obstacles[i].box))
          for (const Loop& loop : w.obstacles[i].boundary) shared[i] += clipped_area(loop, at);
    }
    for (std::size_t i = 0; i < w.obstacles.size(); ++i)
      if (shared[i] > w.area_slack()) {
        char amount[48];
        std::snprintf(amount, sizeof amount, " (area %.3g)", shared[i]);
        return "robot part " + std::to_string(k) + " overlaps " + w.obstacles[i].name + amount;
      }
  }
  return std::nullopt;
}

// The samples of the motion from `a` to `b`, both ends included: a turn every `degrees_step` the
// short way round, a translation every `translation_step` at a's angle.
inline std::vector<Sample> samples(const Pose& a, const Pose& b, double degrees_step, double translation_step) {
  const double ax = to_double(a.position.x), ay = to_double(a.position.y);
  const double from = degrees_of(a.rotation);
  std::vector<Sample> out;
  if (a.position == b.position) {
    const double turn = turn_degrees(a.rotation, b.rotation);
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / degrees_step)));
    for (int k = 0; k <= n; ++k) out.push_back({ax, ay, from + turn * k / n});
  } else {
    const double bx = to_double(b.position.x), by = to_double(b.position.y);
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(bx - ax, by - ay) / translation_step)));
    for (int k = 0; k <= n; ++k) out.push_back({ax + (bx - ax) * k / n, ay + (by - ay) * k / n, from});
  }
  return out;
}

}  // namespace pose_check_detail

// Whether every step of `path` is one motion the rotation planner may return: a translation (the
// rotation kept) or a turn on the spot (the position kept). A repeated pose is a motion of length
// zero and passes. Returns the first offending step, or nullopt.
inline std::optional<std::string> check_motions_are_single(const std::vector<Pose>& path) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!(path[i].position == path[i + 1].position) && !(path[i].rotation == path[i + 1].rotation))
      return "motion " + std::to_string(i) + " (" + to_string(path[i]) + " → " + to_string(path[i + 1]) +
             ") both moves and turns";
  return std::nullopt;
}

// Re-checks `path` by sampling every motion densely in doubles (see the top of this file): turns
// every `degrees_step` degrees, translations every `translation_step` (0: the world's diagonal /
// 2000, the diagonal of its bounds or else of its obstacles and the path). At each sample every
// robot part must stay inside the bounds and share with no obstacle more area than rounding.
// Returns the first failure, naming the motion, the sampled pose and what it hits; or nullopt.
inline std::optional<std::string> sampled_overlap(const World& world, const std::vector<Pose>& path,
                                                  double degrees_step = 0.01, double translation_step = 0) {
  using namespace pose_check_detail;
  if (auto mixed = check_motions_are_single(path)) return mixed;
  const SampledWorld sampled(world, path);
  if (translation_step <= 0) translation_step = sampled.diagonal / 2000;
  if (path.size() == 1)
    if (auto hit = overlap_at(
            sampled, {to_double(path[0].position.x), to_double(path[0].position.y), degrees_of(path[0].rotation)}))
      return "pose 0 " + to_string(path[0]) + ": " + *hit;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    for (const Sample& s : samples(path[i], path[i + 1], degrees_step, translation_step))
      if (auto hit = overlap_at(sampled, s))
        return "motion " + std::to_string(i) + " (" + to_string(path[i]) + " → " + to_string(path[i + 1]) + ") at " +
               describe(s) + ": " + *hit;
  return std::nullopt;
}

}  // namespace polyplan::test
