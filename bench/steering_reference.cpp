// The frozen OMPL reference for polyplan's Dubins and Reeds–Shepp curves (tests/data/car/): for a
// fixed list of pose pairs, OMPL's answer, written once so that the tests compare against it
// without OMPL (a benchmark-only dependency, not installed where the tests run).
//
//   steering_reference OUT_DIR   writes OUT_DIR/ompl_dubins.csv, OUT_DIR/ompl_reeds_shepp.csv
//                                and OUT_DIR/steering_cases.txt
//
// Each CSV row: x0,y0,theta0,x1,y1,theta1,radius,length,end_x,end_y,end_theta, every double with
// %.17g (it reads back to the same double). length is distance() of ompl::base::DubinsStateSpace
// / ReedsSheppStateSpace with that radius; end_* is where OMPL's own path ends, its segments
// (dubins() / reedsShepp()) driven from the start pose here — interpolate(from, to, 1.0) would
// only copy the goal, and hide a path that does not reach it (OMPL's dubins() answers a straight
// for poses under 1e-6 apart with headings under 1e-6 apart, wherever the goal lies). end_theta
// is put in [-pi, pi) by OMPL's SO2StateSpace::enforceBounds, as OMPL's interpolate does.
//
// Rows: first the degenerate pairs, each named in steering_cases.txt ("ROW NAME", ROW 0-based
// among the data rows), then 10,000 random pairs (random_pairs below: the rule that
// bench/steering_bench.cpp repeats). Both CSVs hold the same pairs in the same order. Debian's
// OMPL keeps its assert()s, and a few fail on pairs far apart: each query is tried first in a
// child process, and a pair OMPL aborts on is left out of both CSVs (named in their comment line).
// A summary goes to stderr: the degenerate rows whose OMPL path ends off the goal.
//
// OMPL only, not polyplan: the reference must not depend on the code it checks.
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace ob = ompl::base;
constexpr double pi = std::numbers::pi;
constexpr double miss_tolerance = 1e-9;

struct Pose {
  double x = 0, y = 0, theta = 0;
};

struct PosePair {
  Pose from, to;
  double radius = 1;
  std::string name;  // degenerate pairs only
};

// ---------------------------------------------------------------------------------------------
// Driving a path: the arcs' and straights' formulas of OMPL's interpolate, scaled by the radius.

enum class Turn { left, straight, right };

// `pose` after `v` of one segment (an arc's angle in radians, a straight's length in radii;
// negative = in reverse).
Pose drive(Pose p, Turn turn, double v, double radius) {
  const double th = p.theta;
  switch (turn) {
    case Turn::left:
      return {p.x + radius * (std::sin(th + v) - std::sin(th)), p.y + radius * (-std::cos(th + v) + std::cos(th)),
              th + v};
    case Turn::right:
      return {p.x + radius * (-std::sin(th - v) + std::sin(th)), p.y + radius * (std::cos(th - v) - std::cos(th)),
              th - v};
    case Turn::straight: return {p.x + radius * v * std::cos(th), p.y + radius * v * std::sin(th), th};
  }
  return p;
}

// A heading in [-pi, pi), as OMPL keeps its SO2 states.
double ompl_heading(double theta) {
  static const auto so2 = std::make_shared<ob::SO2StateSpace>();
  ob::ScopedState<ob::SO2StateSpace> s(so2);
  s->value = theta;
  so2->enforceBounds(s.get());
  return s->value;
}

Turn turn_of(ob::DubinsStateSpace::DubinsPathSegmentType type) {
  if (type == ob::DubinsStateSpace::DUBINS_LEFT) return Turn::left;
  if (type == ob::DubinsStateSpace::DUBINS_RIGHT) return Turn::right;
  return Turn::straight;
}

Turn turn_of(ob::ReedsSheppStateSpace::ReedsSheppPathSegmentType type) {
  if (type == ob::ReedsSheppStateSpace::RS_LEFT) return Turn::left;
  if (type == ob::ReedsSheppStateSpace::RS_RIGHT) return Turn::right;
  return Turn::straight;
}

// ---------------------------------------------------------------------------------------------
// OMPL's answer for one pair.

struct Answer {
  double length = 0;       // distance()
  double path_length = 0;  // the path's own segments, radius · Σ|length_i|: should equal length
  Pose end;
};

ob::ScopedState<ob::SE2StateSpace> se2_state(const std::shared_ptr<ob::SE2StateSpace>& space, const Pose& p) {
  ob::ScopedState<ob::SE2StateSpace> s(space);
  s->setX(p.x);
  s->setY(p.y);
  s->setYaw(p.theta);
  return s;
}

Answer ompl_dubins(const PosePair& pair) {
  const auto space = std::make_shared<ob::DubinsStateSpace>(pair.radius);
  const auto a = se2_state(space, pair.from), b = se2_state(space, pair.to);
  const ob::DubinsStateSpace::DubinsPath path = space->dubins(a.get(), b.get());
  if (path.reverse_) std::cerr << "steering_reference: OMPL's dubins() returned a reversed path; driven forward\n";
  Answer answer{space->distance(a.get(), b.get()), 0, pair.from};
  for (int i = 0; i < 3; ++i) {
    answer.end = drive(answer.end, turn_of(path.type_[i]), path.length_[i], pair.radius);
    answer.path_length += pair.radius * std::abs(path.length_[i]);
  }
  answer.end.theta = ompl_heading(answer.end.theta);
  return answer;
}

Answer ompl_reeds_shepp(const PosePair& pair) {
  const auto space = std::make_shared<ob::ReedsSheppStateSpace>(pair.radius);
  const auto a = se2_state(space, pair.from), b = se2_state(space, pair.to);
  const ob::ReedsSheppStateSpace::ReedsSheppPath path = space->reedsShepp(a.get(), b.get());
  Answer answer{space->distance(a.get(), b.get()), 0, pair.from};
  // OMPL's interpolate stops at the first RS_NOP.
  for (int i = 0; i < 5 && path.type_[i] != ob::ReedsSheppStateSpace::RS_NOP; ++i) {
    answer.end = drive(answer.end, turn_of(path.type_[i]), path.length_[i], pair.radius);
    answer.path_length += pair.radius * std::abs(path.length_[i]);
  }
  answer.end.theta = ompl_heading(answer.end.theta);
  return answer;
}

// ---------------------------------------------------------------------------------------------
// The degenerate pairs, for each radius: where a closed form divides by zero, takes an arc
// cosine at ±1, or compares angles across the ±pi seam.

class Degenerate {
 public:
  explicit Degenerate(double radius) : radius_(radius) {
    std::ostringstream text;
    text << radius;
    suffix_ = "_r" + text.str();
  }

  std::vector<PosePair> all() {
    same_pose();
    on_turning_circle();
    exact_headings();
    nearly_same_pose();
    far_apart();
    return std::move(pairs_);
  }

 private:
  void add(const std::string& name, Pose from, Pose to) { pairs_.push_back({from, to, radius_, name + suffix_}); }

  // Start = goal: the empty path (or, where an implementation breaks, a full circle).
  void same_pose() {
    for (const auto& [name, theta] : headings_with_minus_pi) add("same_h" + name, {0, 0, theta}, {0, 0, theta});
    add("same_h1rad", {0, 0, 1.0}, {0, 0, 1.0});
    add("same_off_origin", {3, -2, 0.3}, {3, -2, 0.3});
    add("same_seam_pi_to_minus_pi", {0, 0, pi}, {0, 0, -pi});
  }

  // The goal the pose after an exact arc of the start's left or right turning circle: a one-arc
  // path, and the words with a zero-length segment beside it.
  void on_turning_circle() {
    const std::array<Pose, 2> starts{Pose{0, 0, 0}, Pose{1.5, -2, 0.3}};
    for (std::size_t s = 0; s < starts.size(); ++s)
      for (Turn turn : {Turn::left, Turn::right})
        for (int degrees : {45, 90, 180, 270}) {
          Pose goal = drive(starts[s], turn, degrees * pi / 180, radius_);
          goal.theta = ompl_heading(goal.theta);
          add(std::string("circle_") + (turn == Turn::left ? "left" : "right") + std::to_string(degrees) +
                  (s == 0 ? "_o" : "_p"),
              starts[s], goal);
        }
  }

  // Headings exactly 0, ±90°, 180°, the goal exactly ahead, behind or beside at 3 and at 2·radius
  // (beside at 2·radius with the opposite heading is a half turn of the circle).
  void exact_headings() {
    struct Axis {
      const char* name;
      double theta, ux, uy;  // the heading and its exact unit vector
    };
    const std::array<Axis, 4> axes{Axis{"0", 0, 1, 0}, Axis{"90", pi / 2, 0, 1}, Axis{"-90", -pi / 2, 0, -1},
                                   Axis{"180", pi, -1, 0}};
    for (const Axis& start : axes)
      for (const auto& [where, side, ahead] : std::array<std::tuple<const char*, double, double>, 4>{
               {{"ahead", 0, 1}, {"behind", 0, -1}, {"left", 1, 0}, {"right", -1, 0}}})
        for (const auto& [dname, d] :
             std::array<std::pair<const char*, double>, 2>{{{"d3", 3.0}, {"d2R", 2 * radius_}}})
          for (const Axis& goal : axes) {
            // ahead along (ux, uy), left along (-uy, ux)
            const double gx = d * (ahead * start.ux - side * start.uy), gy = d * (ahead * start.uy + side * start.ux);
            add(std::string("axis_h") + start.name + "_" + where + "_" + dname + "_g" + goal.name, {0, 0, start.theta},
                {gx, gy, goal.theta});
          }
  }

  // Poses 1e-9 apart — below OMPL's 1e-6 shortcut — ahead, behind or beside, with equal or
  // opposite headings; headings 1e-9 apart; and the same across the ±pi seam.
  void nearly_same_pose() {
    constexpr double e = 1e-9;
    struct Start {
      const char* name;
      double theta, ux, uy;
    };
    const std::array<Start, 2> starts{Start{"0", 0, 1, 0}, Start{"0.7", 0.7, std::cos(0.7), std::sin(0.7)}};
    for (const Start& s : starts)
      for (const auto& [where, side, ahead] : std::array<std::tuple<const char*, double, double>, 4>{
               {{"ahead", 0, 1}, {"behind", 0, -1}, {"left", 1, 0}, {"right", -1, 0}}})
        for (bool opposite : {false, true}) {
          const double gx = e * (ahead * s.ux - side * s.uy), gy = e * (ahead * s.uy + side * s.ux);
          const double goal_theta = opposite ? ompl_heading(s.theta + pi) : s.theta;
          add(std::string("tiny_") + where + (opposite ? "_opposite" : "_same") + "_h" + s.name, {0, 0, s.theta},
              {gx, gy, goal_theta});
        }
    add("tiny_turn_plus", {0, 0, 0}, {0, 0, e});
    add("tiny_turn_minus", {0, 0, 0}, {0, 0, -e});
    add("tiny_seam_turn", {0, 0, pi - e / 2}, {0, 0, -pi + e / 2});
    add("tiny_seam_ahead", {0, 0, pi}, {-e, 0, -pi});
  }

  // Poses 1e6 apart: long straights, where the arcs' rounding meets a large coordinate.
  void far_apart() {
    constexpr double far = 1e6;
    add("far_ahead", {0, 0, 0}, {far, 0, 0});
    add("far_behind", {0, 0, 0}, {-far, 0, 0});
    add("far_left", {0, 0, 0}, {0, far, 0});
    add("far_right", {0, 0, 0}, {0, -far, 0});
    add("far_ahead_opposite", {0, 0, 0}, {far, 0, pi});
    add("far_left_facing", {0, 0, 0}, {0, far, pi / 2});
    add("far_off_origin", {far, -far, 1.0}, {0, -far, -2.0});
  }

  inline static const std::vector<std::pair<std::string, double>> headings_with_minus_pi{
      {"0", 0}, {"90", pi / 2}, {"-90", -pi / 2}, {"180", pi}, {"-180", -pi}};

  double radius_;
  std::string suffix_;
  std::vector<PosePair> pairs_;
};

std::vector<PosePair> degenerate_pairs() {
  std::vector<PosePair> pairs;
  for (double radius : {1.0, 0.25, 7.5}) {
    auto more = Degenerate(radius).all();
    pairs.insert(pairs.end(), more.begin(), more.end());
  }
  return pairs;
}

// The random pairs; bench/steering_bench.cpp draws the same ones with the same rule: for each pair
// x0, y0, theta0, x1, y1, theta1, then the radius's index, from one std::mt19937_64 seeded 2026.
constexpr std::uint64_t random_seed = 2026;
constexpr std::size_t random_count = 10000;
constexpr std::array<double, 4> random_radii{1, 0.5, 2, 3.7};

std::vector<PosePair> random_pairs() {
  std::mt19937_64 rng(random_seed);
  std::uniform_real_distribution<double> coordinate(-10, 10), heading(-pi, pi);
  std::uniform_int_distribution<std::size_t> radius_index(0, random_radii.size() - 1);
  std::vector<PosePair> pairs(random_count);
  for (PosePair& p : pairs) {
    p.from.x = coordinate(rng), p.from.y = coordinate(rng), p.from.theta = heading(rng);
    p.to.x = coordinate(rng), p.to.y = coordinate(rng), p.to.theta = heading(rng);
    p.radius = random_radii[radius_index(rng)];
  }
  return pairs;
}

// ---------------------------------------------------------------------------------------------
// Output.

struct Miss {
  double distance = 0, heading = 0;  // of the path's end from the goal; heading wrapped to [-pi, pi]
  double worst() const { return std::max(distance, std::abs(heading)); }
};

Miss miss(const Answer& a, const Pose& goal) {
  return {std::hypot(a.end.x - goal.x, a.end.y - goal.y), std::remainder(a.end.theta - goal.theta, 2 * pi)};
}

struct CsvFile {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, std::fclose};

  CsvFile(const std::filesystem::path& path, const std::string& how)
      : file(std::fopen(path.c_str(), "w"), std::fclose) {
    if (!file) throw std::runtime_error("cannot write " + path.string());
    std::fputs("x0,y0,theta0,x1,y1,theta1,radius,length,end_x,end_y,end_theta\n", file.get());
    std::fprintf(file.get(), "# %s\n", how.c_str());
  }
  void row(const PosePair& p, const Answer& a) {
    const std::array<double, 11> v{p.from.x, p.from.y, p.from.theta, p.to.x,  p.to.y,     p.to.theta,
                                   p.radius, a.length, a.end.x,      a.end.y, a.end.theta};
    for (std::size_t i = 0; i < v.size(); ++i) std::fprintf(file.get(), i == 0 ? "%.17g" : ",%.17g", v[i]);
    std::fputc('\n', file.get());
  }
  void close(const std::filesystem::path& path) {
    if (std::ferror(file.get()) != 0 || std::fclose(file.release()) != 0)
      throw std::runtime_error("cannot write " + path.string());
  }
};

std::string provenance(const char* space, const std::string& command, std::size_t degenerate) {
  std::ostringstream how;
  // No commas: the line stays one field to a CSV reader that does not skip comments.
  how << "made by bench/steering_reference.cpp (" << command << ") with OMPL " << OMPL_MAJOR_VERSION << '.'
      << OMPL_MINOR_VERSION << '.' << OMPL_PATCH_VERSION << " ompl::base::" << space
      << ": length = distance(); end_* = OMPL's path segments driven "
      << "from the start (end_theta in [-pi pi)); rows 0-" << degenerate - 1
      << " the degenerate pairs of steering_cases.txt; then " << random_count
      << " random pairs from std::mt19937_64 seed " << random_seed
      << ": each draws x0 y0 (uniform_real -10..10) theta0 (uniform_real -pi..pi) x1 y1 theta1 alike; then the radius "
         "{1 0.5 2 3.7}[uniform_int 0..3]";
  return how.str();
}

// A degenerate row's miss: every row whose path ends off the goal at all (beyond rounding at the
// scale of the coordinates), flagged where it exceeds miss_tolerance — the rows the tests name.
void report_miss(std::size_t row, const PosePair& p, const char* which, const Answer& a) {
  const Miss m = miss(a, p.to);
  const double scale = std::max({1.0, std::abs(p.to.x), std::abs(p.to.y)});
  if (m.worst() <= 1e-14 * scale) return;
  std::fprintf(stderr, "  %s row %zu %s %s: misses the goal by %.3g, heading by %.3g rad; length %.17g\n",
               m.worst() > miss_tolerance ? "MISS" : "    ", row, p.name.c_str(), which, m.distance, m.heading,
               a.length);
}

// Where distance() and the path's own segments disagree (they should not: both are OMPL's).
void check_lengths(std::size_t row, const char* which, const Answer& a) {
  if (std::abs(a.length - a.path_length) > 1e-12 * std::max(1.0, a.length))
    std::fprintf(stderr, "  row %zu %s: distance() %.17g but the path's segments sum to %.17g\n", row, which, a.length,
                 a.path_length);
}

void write_cases(const std::filesystem::path& path, const std::vector<PosePair>& pairs) {
  std::ofstream out(path);
  for (std::size_t row = 0; row < pairs.size(); ++row)
    if (!pairs[row].name.empty()) out << row << ' ' << pairs[row].name << '\n';
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

struct RandomSummary {
  std::size_t misses = 0;
  double worst = 0;
  void add(const Answer& a, const Pose& goal) {
    const double w = miss(a, goal).worst();
    misses += w > miss_tolerance;
    worst = std::max(worst, w);
  }
};

// ---------------------------------------------------------------------------------------------
// Debian's libompl is built with its assert()s on, and some fail (abort the process) on pairs far
// apart in units of the radius. Each query runs first in a child process; a pair that either
// space aborts on is left out of both CSVs (they hold the same pairs) and named in their comment.

// OMPL's message when `query` aborts on `pair`; empty when it answers.
std::string ompl_abort(const PosePair& pair, Answer (*query)(const PosePair&)) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(fds[0]);
    dup2(fds[1], STDERR_FILENO);
    query(pair);
    _exit(0);
  }
  close(fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  message = message.substr(0, message.find('\n'));
  return message.empty() ? "killed by signal " + std::to_string(WTERMSIG(status)) : message;
}

// `pairs` without those OMPL aborts on; the left-out ones' names (or random indices) in `left_out`.
std::vector<PosePair> answerable(const std::vector<PosePair>& pairs, std::string& left_out) {
  std::vector<PosePair> kept;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string dubins = ompl_abort(pairs[i], ompl_dubins), reeds_shepp = ompl_abort(pairs[i], ompl_reeds_shepp);
    if (dubins.empty() && reeds_shepp.empty()) {
      kept.push_back(pairs[i]);
      continue;
    }
    const std::string name = pairs[i].name.empty() ? "random pair " + std::to_string(i) : pairs[i].name;
    left_out += (left_out.empty() ? "" : " ") + name + "(" + (dubins.empty() ? "" : "Dubins") +
                (dubins.empty() || reeds_shepp.empty() ? "" : "+") + (reeds_shepp.empty() ? "" : "ReedsShepp") + ")";
    std::cerr << "left out " << name << ": OMPL aborts — " << (dubins.empty() ? "" : "Dubins: " + dubins + "; ")
              << (reeds_shepp.empty() ? "" : "Reeds-Shepp: " + reeds_shepp) << '\n';
  }
  return kept;
}

// ---------------------------------------------------------------------------------------------

int run(const std::filesystem::path& out_dir, const std::string& command) {
  std::string left_out;
  std::vector<PosePair> pairs = answerable(degenerate_pairs(), left_out);
  const std::size_t degenerate = pairs.size();
  std::string random_left_out;
  const std::vector<PosePair> random = answerable(random_pairs(), random_left_out);
  if (!random_left_out.empty())
    throw std::runtime_error("OMPL aborts on random pairs (" + random_left_out + "): the rule needs changing");
  pairs.insert(pairs.end(), random.begin(), random.end());

  const std::string omitted = left_out.empty() ? "" : "; left out (OMPL's assertions abort on them): " + left_out;
  std::filesystem::create_directories(out_dir);
  CsvFile dubins(out_dir / "ompl_dubins.csv", provenance("DubinsStateSpace", command, degenerate) + omitted);
  CsvFile reeds_shepp(out_dir / "ompl_reeds_shepp.csv",
                      provenance("ReedsSheppStateSpace", command, degenerate) + omitted);
  RandomSummary random_dubins, random_reeds_shepp;
  std::cerr << "steering_reference: degenerate rows whose OMPL path ends off the goal (MISS: by more than "
            << miss_tolerance << "):\n";
  for (std::size_t row = 0; row < pairs.size(); ++row) {
    const PosePair& p = pairs[row];
    const Answer d = ompl_dubins(p), rs = ompl_reeds_shepp(p);
    dubins.row(p, d);
    reeds_shepp.row(p, rs);
    check_lengths(row, "dubins", d);
    check_lengths(row, "reeds_shepp", rs);
    if (row < degenerate) {
      report_miss(row, p, "dubins", d);
      report_miss(row, p, "reeds_shepp", rs);
    } else {
      random_dubins.add(d, p.to);
      random_reeds_shepp.add(rs, p.to);
    }
  }
  dubins.close(out_dir / "ompl_dubins.csv");
  reeds_shepp.close(out_dir / "ompl_reeds_shepp.csv");
  write_cases(out_dir / "steering_cases.txt", pairs);
  std::fprintf(stderr, "random rows: dubins %zu over %g (worst %.3g), reeds_shepp %zu over %g (worst %.3g)\n",
               random_dubins.misses, miss_tolerance, random_dubins.worst, random_reeds_shepp.misses, miss_tolerance,
               random_reeds_shepp.worst);
  std::fprintf(stderr, "wrote %zu rows (%zu degenerate, %zu random) to each CSV in %s\n", pairs.size(), degenerate,
               random.size(), out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: steering_reference OUT_DIR\n";
    return 2;
  }
  try {
    return run(argv[1], std::string("steering_reference ") + argv[1]);
  } catch (const std::exception& e) {
    std::cerr << "steering_reference: " << e.what() << '\n';
    return 1;
  }
}
