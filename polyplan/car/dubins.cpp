#include <polyplan/car/dubins.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace polyplan {
namespace {

constexpr double two_pi = 2 * M_PI;

// An angle in [0, 2 pi). A value a few rounding errors below 2 pi is 0: it comes from an angle
// that is 0 exactly (start on the goal's circle, or start = goal) computed as a tiny negative,
// and taken literally it would drive a full circle instead of none.
double turn(double angle) {
  double a = angle - two_pi * std::floor(angle / two_pi);
  if (a >= two_pi - 1e-11) a = 0;
  return a;
}

// The problem in the frame of the Dubins formulas: the start at the origin, the goal at (d, 0),
// lengths in turning radii, the headings alpha and beta measured from the start-goal line.
struct DubinsFrame {
  double d, alpha, beta;
  double sa, ca, sb, cb;
};

DubinsFrame frame(const CarPose& from, const CarPose& to, double radius) {
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double d = std::hypot(dx, dy) / radius;  // up to 1e200 (require_steerable): no overflow below
  // Poses at one point: any line through it serves; the start's heading makes alpha 0 exactly.
  const double line = d > 0 ? std::atan2(dy, dx) : from.theta;
  const double alpha = turn(from.theta - line), beta = turn(to.theta - line);
  return {d, alpha, beta, std::sin(alpha), std::cos(alpha), std::sin(beta), std::cos(beta)};
}

struct Word {
  const char* letters;
  double t, p, q;  // in turning radii (arcs: radians)
  double length() const { return t + p + q; }
};

// Each word from the centres of its turning circles (left of the car: (-sin, cos) from it;
// right: (sin, -cos)), which keeps the straight's length free of cancellation.
std::optional<Word> lsl(const DubinsFrame& f) {
  const double x = f.d - f.sb + f.sa, y = f.cb - f.ca;
  const double line = std::atan2(y, x);
  return Word{"LSL", turn(line - f.alpha), std::hypot(x, y), turn(f.beta - line)};
}

std::optional<Word> rsr(const DubinsFrame& f) {
  const double x = f.d + f.sb - f.sa, y = f.ca - f.cb;
  const double line = std::atan2(y, x);
  return Word{"RSR", turn(f.alpha - line), std::hypot(x, y), turn(line - f.beta)};
}

// The inner tangent between circles whose centres are `centres` apart: none when they overlap.
// sqrt(D - 2) sqrt(D + 2), not sqrt(D^2 - 4): no cancellation near tangent circles, no overflow
// for centres far apart.
std::optional<double> inner_tangent(double centres) {
  if (centres < 2 - 1e-12) return std::nullopt;
  return std::sqrt(std::max(0.0, centres - 2)) * std::sqrt(centres + 2);
}

std::optional<Word> lsr(const DubinsFrame& f) {
  const double x = f.d + f.sa + f.sb, y = -f.ca - f.cb;
  const auto p = inner_tangent(std::hypot(x, y));
  if (!p) return std::nullopt;
  const double line = std::atan2(y, x) - std::atan2(-2.0, *p);
  return Word{"LSR", turn(line - f.alpha), *p, turn(line - f.beta)};
}

std::optional<Word> rsl(const DubinsFrame& f) {
  const double x = f.d - f.sa - f.sb, y = f.ca + f.cb;
  const auto p = inner_tangent(std::hypot(x, y));
  if (!p) return std::nullopt;
  const double line = std::atan2(y, x) - std::atan2(2.0, *p);
  return Word{"RSL", turn(f.alpha - line), *p, turn(f.beta - line)};
}

// The middle circle of RLR or LRL touches both end circles, whose centres are `centres` <= 4
// apart: it turns 2 pi less the angle 2 asin(centres / 4) at its centre (the law of cosines'
// acos(1 - centres^2 / 8) loses every digit when the centres nearly coincide).
std::optional<double> middle_turn(double centres) {
  if (centres > 4 + 1e-12) return std::nullopt;
  return 2 * M_PI - 2 * std::asin(std::min(1.0, centres / 4));
}

std::optional<Word> rlr(const DubinsFrame& f) {
  const double x = f.d + f.sb - f.sa, y = f.ca - f.cb;
  const auto p = middle_turn(std::hypot(x, y));
  if (!p) return std::nullopt;
  const double t = turn(f.alpha - std::atan2(y, x) + *p / 2);
  return Word{"RLR", t, *p, turn(f.alpha - f.beta - t + *p)};
}

std::optional<Word> lrl(const DubinsFrame& f) {
  const double x = f.d - f.sb + f.sa, y = f.cb - f.ca;
  const auto p = middle_turn(std::hypot(x, y));
  if (!p) return std::nullopt;
  const double t = turn(std::atan2(y, x) - f.alpha + *p / 2);
  return Word{"LRL", t, *p, turn(f.beta - f.alpha - t + *p)};
}

SteeringPath path_of(const Word& w, double radius, bool snap) {
  SteeringPath path;
  const double lengths[] = {w.t, w.p, w.q};
  for (int i = 0; i < 3; ++i)
    append_segment(path, static_cast<Steer>(w.letters[i]), 1, lengths[i] * radius, radius, false, snap);
  return path;
}

// The six words, in the order steer --all-words lists them.
constexpr struct {
  const char* name;
  std::optional<Word> (*solve)(const DubinsFrame&);
} every_word[] = {{"LSL", lsl}, {"RSR", rsr}, {"LSR", lsr}, {"RSL", rsl}, {"RLR", rlr}, {"LRL", lrl}};

// Each of the six, none where it cannot join the poses.
std::vector<std::optional<Word>> words(const CarPose& from, const CarPose& to, double radius) {
  require_steerable(from, to, radius, "dubins");
  const DubinsFrame f = frame(from, to, radius);
  std::vector<std::optional<Word>> found;
  for (const auto& word : every_word) found.push_back(word.solve(f));
  return found;
}

ShortestWord shortest_word(const std::vector<std::optional<Word>>& candidates, const CarPose& from, const CarPose& to,
                           double radius) {
  return shortest_reaching(candidates, from, to, radius, "dubins",
                           [radius](const Word& w, bool snap) { return path_of(w, radius, snap); });
}

}  // namespace

std::vector<SteeringPath> dubins_paths(const CarPose& from, const CarPose& to, double radius) {
  std::vector<SteeringPath> paths;
  for (const auto& w : words(from, to, radius))
    if (w) paths.push_back(path_of(*w, radius, true));
  return paths;
}

SteeringPath shortest_dubins_path(const CarPose& from, const CarPose& to, double radius) {
  return shortest_word(words(from, to, radius), from, to, radius).path;
}

SteeringWords dubins_words(const CarPose& from, const CarPose& to, double radius) {
  const auto candidates = words(from, to, radius);
  return listed_words(shortest_word(candidates, from, to, radius), candidates, radius,
                      [](std::size_t i) { return std::string(every_word[i].name); });
}

double dubins_distance(const CarPose& from, const CarPose& to, double radius) {
  return shortest_dubins_path(from, to, radius).length();
}

}  // namespace polyplan
