#pragma once
// A steered car's path between two poses: arcs at full lock and straights, each driven forward or
// in reverse — the curves of Dubins (forward only) and of Reeds and Shepp (either gear), and the
// poses along them. The reference point is the rear-axle centre; the car turns about a centre
// `radius` to its left or right.
#include <polyplan/geometry/car_pose.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct SteeringPath {
  // The segments' letters: "LSR" for a Dubins path; "L+R-L+" for a Reeds–Shepp path (each
  // letter with its gear). A segment of no length is left out: straight ahead is "S".
  std::string word;
  std::vector<SteeringSegment> segments;
  double length() const;
};

// Appends a segment driving `length` (its letter to the word, with the gear's sign when `gears`),
// unless it is no length, or, when `snap`, shorter than 1e-14 turning radii: the rounding of a
// segment that is 0 exactly.
void append_segment(SteeringPath& path, Steer steer, int gear, double length, double radius, bool gears, bool snap);

// The pose reached after driving the first `s` of `path` (clamped to [0, length]) from `start`,
// turning with `radius`.
CarPose pose_along(const SteeringPath& path, const CarPose& start, double radius, double s);
CarPose end_pose(const SteeringPath& path, const CarPose& start, double radius);

// How far the path's end misses `to`: the larger of the distance between the reference points and
// the heading error (wrapped to [0, pi]) times `radius`, so both are lengths.
double goal_miss(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius);

// The turning radii and coordinates steering takes: a radius in [1e-100, 1e100], coordinates of at
// most 1e100 in magnitude, headings finite (geometry/input_limits.hpp's range: the formulas work in
// turning radii, and distances over radii up to 1e200 neither overflow nor lose the curve).
// InputError naming `what` and the range otherwise.
void require_steerable(const CarPose& from, const CarPose& to, double radius, const char* what);

// Whether `path` from `from` reaches `to` as a steering curve must: within 1e-9 of its own length
// plus the rounding of the coordinates (1e-13 of the largest). A word whose segments were rounded
// to zero, or a radius so large against the poses that a curve's arcs swallow the distance
// between them in rounding, misses by more: the next word is taken.
bool reaches(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius);

// The shortest of `candidates` (words in turning radii, each made into a path by `make(word,
// snap)`) that reaches `to`: each tried with its zero-length rounding snapped, then as computed;
// of words equally short, the one of fewest segments. InputError naming `what` when none reaches.
template <class Word, class Make>
SteeringPath shortest_reaching(std::vector<Word> candidates, const CarPose& from, const CarPose& to, double radius,
                               const char* what, Make make);

// Throws the InputError of shortest_reaching.
[[noreturn]] void throw_unreachable(const CarPose& from, const CarPose& to, double radius, const char* what);

template <class Word, class Make>
SteeringPath shortest_reaching(std::vector<Word> candidates, const CarPose& from, const CarPose& to, double radius,
                               const char* what, Make make) {
  std::sort(candidates.begin(), candidates.end(), [](const Word& a, const Word& b) { return a.length() < b.length(); });
  std::optional<SteeringPath> best;
  for (const Word& word : candidates) {
    // Words as long as the best within rounding (a straight, or three arcs of 1e-11 radians
    // each that end where it does): the one of fewer segments.
    if (best && word.length() * radius > best->length() * (1 + 1e-12)) break;
    for (bool snap : {true, false})
      if (SteeringPath path = make(word, snap); reaches(path, from, to, radius)) {
        if (!best || path.segments.size() < best->segments.size()) best = std::move(path);
        break;
      }
  }
  if (!best) throw_unreachable(from, to, radius, what);
  return *best;
}

}  // namespace polyplan
