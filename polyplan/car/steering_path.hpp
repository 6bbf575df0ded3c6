#pragma once
// A steered car's path between two poses: arcs at full lock and straights, each driven forward or
// in reverse — the curves of Dubins (forward only) and of Reeds and Shepp (either gear), and the
// poses along them. The reference point is the rear-axle centre; the car turns about a centre
// `radius` to its left or right.
#include <polyplan/geometry/car_pose.hpp>

#include <algorithm>
#include <cstddef>
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

// One word a solver tries for a pose pair, whether or not it joins them (steer --all-words).
struct SteeringWord {
  // Dubins: "LSL". Reeds–Shepp: the letters with the gears its formula fixes, "L+R-L" where the
  // last arc's gear is the solution's (reeds_shepp.cpp's formulas are named so).
  std::string name;
  std::optional<double> length;  // none: infeasible (no curve of this word joins the poses)
};

// The shortest path and every word tried for it, in the solver's order; `shortest` indexes the
// word of `path` (the least of the feasible words, unless rounding keeps it off the goal).
struct SteeringWords {
  SteeringPath path;
  std::vector<SteeringWord> words;
  std::size_t shortest = 0;
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

// The shortest of `candidates` (words in turning radii, none where a word is infeasible; each
// made into a path by `make(word, snap)`) that reaches `to`: each tried with its zero-length
// rounding snapped, then as computed; of words equally short, the one of fewest segments. The
// path and its index in `candidates`; InputError naming `what` when none reaches.
struct ShortestWord {
  SteeringPath path;
  std::size_t index = 0;
};
template <class Word, class Make>
ShortestWord shortest_reaching(const std::vector<std::optional<Word>>& candidates, const CarPose& from,
                               const CarPose& to, double radius, const char* what, Make make);

// The words of `candidates` as steer --all-words lists them: `name(i)` names the i-th, its
// length scaled by `radius`.
template <class Word, class Name>
SteeringWords listed_words(ShortestWord shortest, const std::vector<std::optional<Word>>& candidates, double radius,
                           Name name) {
  SteeringWords listed{std::move(shortest.path), {}, shortest.index};
  for (std::size_t i = 0; i < candidates.size(); ++i)
    listed.words.push_back(
        {name(i), candidates[i] ? std::optional<double>(candidates[i]->length() * radius) : std::nullopt});
  return listed;
}

// Throws the InputError of shortest_reaching.
[[noreturn]] void throw_unreachable(const CarPose& from, const CarPose& to, double radius, const char* what);

template <class Word, class Make>
ShortestWord shortest_reaching(const std::vector<std::optional<Word>>& candidates, const CarPose& from,
                               const CarPose& to, double radius, const char* what, Make make) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (candidates[i]) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return candidates[a]->length() < candidates[b]->length(); });
  std::optional<ShortestWord> best;
  for (std::size_t i : order) {
    const Word& word = *candidates[i];
    // Words as long as the best within rounding (a straight, or three arcs of 1e-11 radians
    // each that end where it does): the one of fewer segments.
    if (best && word.length() * radius > best->path.length() * (1 + 1e-12)) break;
    for (bool snap : {true, false})
      if (SteeringPath path = make(word, snap); reaches(path, from, to, radius)) {
        if (!best || path.segments.size() < best->path.segments.size()) best = ShortestWord{std::move(path), i};
        break;
      }
  }
  if (!best) throw_unreachable(from, to, radius, what);
  return std::move(*best);
}

}  // namespace polyplan
