// The formulas are those of Reeds and Shepp's paper (section 8), in the arrangement OMPL's
// ReedsSheppStateSpace uses (BSD licence; its distances are the tests' reference): each base
// formula solves for the goal (x, y, phi) in the start's frame, in turning radii; the time-flip
// (-x, y, -phi) reverses every gear, the reflection (x, -y, -phi) swaps left and right, and a
// "backwards" goal (the start seen from the goal) reverses the order of the segments.
#include <polyplan/car/reeds_shepp.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace polyplan {
namespace {

constexpr double pi = M_PI;
// The formulas' sign tolerance, in turning radii. A segment whose exact length is 0 comes out of
// an atan2 with an error of about the rounding of the coordinates divided by the next segment's
// length: 1e-16 / 2e-3 = 5e-14 for an S of 2e-3 radii followed by an L (the last stretch of an
// S L: found where the tail of a shortest curve, itself shortest, was missed). OMPL's 10 machine
// epsilons rejects it, and the word with it. Lengths within `zero` of 0 are taken as 0 (symmetric()),
// so the curve's end moves by at most a few `zero` radii.
constexpr double zero = 1e-11;

// An angle in (-pi, pi].
double wrap(double angle) {
  double a = std::fmod(angle, 2 * pi);
  if (a <= -pi) a += 2 * pi;
  else if (a > pi) a -= 2 * pi;
  return a;
}

void polar(double x, double y, double& r, double& theta) {
  r = std::hypot(x, y);
  theta = std::atan2(y, x);
}

// A word before it is scaled: up to five letters and their signed lengths (negative: reverse).
struct Word {
  std::array<char, 5> letters{};  // 'L', 'S', 'R'; 0 past the end
  std::array<double, 5> lengths{};
  std::array<double, 5> computed{};  // the lengths before those within `zero` of 0 were made 0
  int size = 0;
  double length() const {
    double sum = 0;
    for (int i = 0; i < size; ++i) sum += std::abs(lengths[i]);
    return sum;
  }
};

using Letters = const char*;

Word word(Letters letters, std::initializer_list<double> lengths) {
  Word w;
  for (double l : lengths) {
    w.letters[w.size] = letters[w.size];
    w.lengths[w.size] = l;
    ++w.size;
  }
  return w;
}

// ---- The base formulas: true when the word joins the origin (heading 0) to (x, y, phi). ----

// 8.1: L+ S+ L+
bool lp_sp_lp(double x, double y, double phi, double& t, double& u, double& v) {
  polar(x - std::sin(phi), y - 1 + std::cos(phi), u, t);
  if (t < -zero) return false;
  v = wrap(phi - t);
  return v >= -zero;
}

// 8.2: L+ S+ R+
bool lp_sp_rp(double x, double y, double phi, double& t, double& u, double& v) {
  double r, theta;
  polar(x + std::sin(phi), y - 1 - std::cos(phi), r, theta);
  if (r < 2) return false;
  u = std::sqrt(r - 2) * std::sqrt(r + 2);  // sqrt(r^2 - 4) without overflow
  t = wrap(theta + std::atan2(2.0, u));
  v = wrap(t - phi);
  return t >= -zero && v >= -zero;
}

// 8.3: L+ R- L
bool lp_rm_l(double x, double y, double phi, double& t, double& u, double& v) {
  double r, theta;
  polar(x - std::sin(phi), y - 1 + std::cos(phi), r, theta);
  if (r > 4) return false;
  u = -2 * std::asin(r / 4);
  t = wrap(theta + u / 2 + pi);
  v = wrap(phi - t + u);
  return t >= -zero && u <= zero;
}

// The last two angles of the CCCC words (8.7, 8.8).
void tau_omega(double u, double v, double xi, double eta, double phi, double& tau, double& omega) {
  const double delta = wrap(u - v), a = std::sin(u) - std::sin(delta), b = std::cos(u) - std::cos(delta) - 1;
  const double t1 = std::atan2(eta * a - xi * b, xi * a + eta * b),
               t2 = 2 * (std::cos(delta) - std::cos(v) - std::cos(u)) + 3;
  tau = t2 < 0 ? wrap(t1 + pi) : wrap(t1);
  omega = wrap(tau - u + v - phi);
}

// 8.7: L+ R+ L- R-
bool lp_rup_lum_rm(double x, double y, double phi, double& t, double& u, double& v) {
  const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi), rho = (2 + std::hypot(xi, eta)) / 4;
  if (rho > 1) return false;
  u = std::acos(rho);
  tau_omega(u, -u, xi, eta, phi, t, v);
  return t >= -zero && v <= zero;
}

// 8.8: L+ R- L- R+
bool lp_rum_lum_rp(double x, double y, double phi, double& t, double& u, double& v) {
  const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi),
               rho = (20 - xi * xi - eta * eta) / 16;  // -inf far away
  if (rho < 0 || rho > 1) return false;
  u = -std::acos(rho);
  if (u < -pi / 2) return false;
  tau_omega(u, u, xi, eta, phi, t, v);
  return t >= -zero && v >= -zero;
}

// 8.9: L+ R-(pi/2) S- L-
bool lp_rm_sm_lm(double x, double y, double phi, double& t, double& u, double& v) {
  double rho, theta;
  polar(x - std::sin(phi), y - 1 + std::cos(phi), rho, theta);
  if (rho < 2) return false;
  const double r = std::sqrt(rho - 2) * std::sqrt(rho + 2);
  u = 2 - r;
  t = wrap(theta + std::atan2(r, -2.0));
  v = wrap(phi - pi / 2 - t);
  return t >= -zero && u <= zero && v <= zero;
}

// 8.10: L+ R-(pi/2) S- R-
bool lp_rm_sm_rm(double x, double y, double phi, double& t, double& u, double& v) {
  double rho, theta;
  polar(-(y - 1 - std::cos(phi)), x + std::sin(phi), rho, theta);
  if (rho < 2) return false;
  t = theta;
  u = 2 - rho;
  v = wrap(t + pi / 2 - phi);
  return t >= -zero && u <= zero && v <= zero;
}

// 8.11: L+ R-(pi/2) S- L-(pi/2) R+
bool lp_rm_slm_rp(double x, double y, double phi, double& t, double& u, double& v) {
  const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi);
  double rho, theta;
  polar(xi, eta, rho, theta);
  if (rho < 2) return false;
  u = 4 - std::sqrt(rho - 2) * std::sqrt(rho + 2);
  if (u > zero) return false;
  t = wrap(std::atan2((4 - u) * xi - 2 * eta, -2 * xi + (u - 4) * eta));
  v = wrap(t - phi);
  return t >= -zero && v >= -zero;
}

using Formula = bool (*)(double, double, double, double&, double&, double&);

// A base formula and the signs its t, u, v are held to (0: either), which give its words' names.
struct Base {
  Formula solve;
  double t, u, v;
};
constexpr Base lsl{lp_sp_lp, 1, 1, 1}, lsr{lp_sp_rp, 1, 1, 1}, lrl{lp_rm_l, 1, -1, 0},
    lrlr_same{lp_rup_lum_rm, 1, 1, -1}, lrlr_turned{lp_rum_lum_rp, 1, -1, 1}, lrsl{lp_rm_sm_lm, 1, -1, -1},
    lrsr{lp_rm_sm_rm, 1, -1, -1}, lrslr{lp_rm_slm_rp, 1, -1, 1};

// The words tried, one slot each (none where the formula does not join the poses), and, when
// asked (steer --all-words), each slot's name.
struct Slots {
  std::vector<std::optional<Word>> words;
  std::vector<std::string>* names = nullptr;
};

// A word's letters with the gears of its lengths: "L+R-L" when the last may be either.
std::string gears_of(const Word& w) {
  std::string name;
  for (int i = 0; i < w.size; ++i) {
    name += w.letters[i];
    if (w.lengths[i] != 0) name += w.lengths[i] > 0 ? '+' : '-';
  }
  return name;
}

// A base formula under the four symmetries; `make` turns its (t, u, v) and the symmetry's sign
// (-1: time-flipped) into the word: `letters` for the goal as given, `mirrored` (left and right
// swapped) for the reflection.
template <class Make>
void symmetric(Slots& out, const Base& base, Letters letters, Letters mirrored, double x, double y, double phi,
               Make make) {
  double t, u, v;
  // A length is within `zero` of 0 exactly when the t, u or v it is made of is (the words' other
  // lengths are fixed quarter turns): snapped where it lies, the computed ones kept beside.
  const auto solved = [&](double gx, double gy, double gphi, Letters l, double sign) -> std::optional<Word> {
    if (out.names) out.names->push_back(gears_of(make(l, sign, base.t, base.u, base.v)));
    if (!base.solve(gx, gy, gphi, t, u, v)) return std::nullopt;
    Word w = make(l, sign, t, u, v);
    w.computed = w.lengths;
    for (int i = 0; i < w.size; ++i)
      if (std::abs(w.lengths[i]) < zero) w.lengths[i] = 0;
    return w;
  };
  out.words.push_back(solved(x, y, phi, letters, 1));
  out.words.push_back(solved(-x, y, -phi, letters, -1));
  out.words.push_back(solved(x, -y, -phi, mirrored, 1));
  out.words.push_back(solved(-x, -y, phi, mirrored, -1));
}

void csc(Slots& out, double x, double y, double phi) {
  const auto make = [](Letters l, double s, double t, double u, double v) { return word(l, {s * t, s * u, s * v}); };
  symmetric(out, lsl, "LSL", "RSR", x, y, phi, make);
  symmetric(out, lsr, "LSR", "RSL", x, y, phi, make);
}

// The goal's "backwards" twin: the start seen from the goal, for the words read in reverse.
void backwards(double x, double y, double phi, double& xb, double& yb) {
  xb = x * std::cos(phi) + y * std::sin(phi);
  yb = x * std::sin(phi) - y * std::cos(phi);
}

void ccc(Slots& out, double x, double y, double phi) {
  symmetric(out, lrl, "LRL", "RLR", x, y, phi, [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * t, s * u, s * v});
  });
  double xb, yb;
  backwards(x, y, phi, xb, yb);
  symmetric(out, lrl, "LRL", "RLR", xb, yb, phi, [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * v, s * u, s * t});
  });
}

void cccc(Slots& out, double x, double y, double phi) {
  symmetric(out, lrlr_same, "LRLR", "RLRL", x, y, phi, [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * t, s * u, -s * u, s * v});
  });
  symmetric(out, lrlr_turned, "LRLR", "RLRL", x, y, phi, [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * t, s * u, s * u, s * v});
  });
}

void ccsc(Slots& out, double x, double y, double phi) {
  const auto forward = [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * t, -s * pi / 2, s * u, s * v});
  };
  symmetric(out, lrsl, "LRSL", "RLSR", x, y, phi, forward);
  symmetric(out, lrsr, "LRSR", "RLSL", x, y, phi, forward);
  double xb, yb;
  backwards(x, y, phi, xb, yb);
  const auto reverse = [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * v, s * u, -s * pi / 2, s * t});
  };
  symmetric(out, lrsl, "LSRL", "RSLR", xb, yb, phi, reverse);
  symmetric(out, lrsr, "RSRL", "LSLR", xb, yb, phi, reverse);
}

void ccscc(Slots& out, double x, double y, double phi) {
  symmetric(out, lrslr, "LRSLR", "RLSRL", x, y, phi, [](Letters l, double s, double t, double u, double v) {
    return word(l, {s * t, -s * pi / 2, s * u, -s * pi / 2, s * v});
  });
}

SteeringPath path_of(const Word& w, double radius, bool snap) {
  SteeringPath path;
  const auto& lengths = snap ? w.lengths : w.computed;
  for (int i = 0; i < w.size; ++i)
    append_segment(path, static_cast<Steer>(w.letters[i]), lengths[i] < 0 ? -1 : 1, std::abs(lengths[i]) * radius,
                   radius, true, snap);
  return path;
}

// Every word tried, in turning radii, the goal in the start's frame; `names` as Slots says.
std::vector<std::optional<Word>> every_word(const CarPose& from, const CarPose& to, double radius,
                                            std::vector<std::string>* names = nullptr) {
  require_steerable(from, to, radius, "reeds-shepp");
  const double dx = to.x - from.x, dy = to.y - from.y, c = std::cos(from.theta), s = std::sin(from.theta);
  const double x = (c * dx + s * dy) / radius, y = (c * dy - s * dx) / radius, phi = wrap(to.theta - from.theta);
  Slots slots{{}, names};
  slots.words.reserve(44);
  csc(slots, x, y, phi);
  ccc(slots, x, y, phi);
  cccc(slots, x, y, phi);
  ccsc(slots, x, y, phi);
  ccscc(slots, x, y, phi);
  return std::move(slots.words);
}

ShortestWord shortest_word(const std::vector<std::optional<Word>>& candidates, const CarPose& from, const CarPose& to,
                           double radius) {
  return shortest_reaching(candidates, from, to, radius, "reeds-shepp",
                           [radius](const Word& w, bool snap) { return path_of(w, radius, snap); });
}

}  // namespace

std::vector<SteeringPath> reeds_shepp_paths(const CarPose& from, const CarPose& to, double radius) {
  std::vector<SteeringPath> paths;
  for (const auto& w : every_word(from, to, radius))
    if (w) paths.push_back(path_of(*w, radius, true));
  return paths;
}

// The least word that reaches the goal: L+S+L+ under one of its symmetries always solves (8.1
// needs only a circle through the goal).
SteeringPath shortest_reeds_shepp_path(const CarPose& from, const CarPose& to, double radius) {
  return shortest_word(every_word(from, to, radius), from, to, radius).path;
}

SteeringWords reeds_shepp_words(const CarPose& from, const CarPose& to, double radius) {
  std::vector<std::string> names;
  const auto candidates = every_word(from, to, radius, &names);
  return listed_words(shortest_word(candidates, from, to, radius), candidates, radius,
                      [&names](std::size_t i) { return names[i]; });
}

double reeds_shepp_distance(const CarPose& from, const CarPose& to, double radius) {
  return shortest_reeds_shepp_path(from, to, radius).length();
}

}  // namespace polyplan
