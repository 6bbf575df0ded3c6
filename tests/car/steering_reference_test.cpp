// polyplan's Dubins and Reeds–Shepp distances against OMPL's (1.5.2, frozen in tests/data/car/
// by bench/steering_reference.cpp): 10,000 seeded random pose pairs and 536 degenerate ones.
// Where OMPL's own path reaches the goal, the lengths agree to 1e-9 relative. Where it does not
// (its Dubins space drives a straight to a goal under 1e-6 away whatever the headings), OMPL's
// length is no reference: polyplan's path must reach the goal, and those cases are named here;
// its Dubins length is checked instead against the shortest path that does reach the goal,
// computed in 256-bit MPFR arithmetic independently of polyplan's code (frozen in
// tests/data/car/dubins_extended.csv by bench/dubins_extended_reference.cpp), to 1e-12 relative.
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace polyplan {
namespace {

std::string reference_file(const std::string& name) {
  return std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/car/" + name;
}

struct ReferenceRow {
  CarPose from, to;
  double radius, length;
  CarPose ompl_end;
};

std::vector<ReferenceRow> read_reference(const std::string& file) {
  std::ifstream in(reference_file(file));
  EXPECT_TRUE(in) << reference_file(file);
  std::vector<ReferenceRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;  // the comment and the header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    ReferenceRow r;
    fields >> r.from.x >> r.from.y >> r.from.theta >> r.to.x >> r.to.y >> r.to.theta >> r.radius >> r.length >>
        r.ompl_end.x >> r.ompl_end.y >> r.ompl_end.theta;
    rows.push_back(r);
  }
  return rows;
}

std::map<std::size_t, std::string> case_names() {
  std::ifstream in(reference_file("steering_cases.txt"));
  std::map<std::size_t, std::string> names;
  std::size_t row;
  std::string name;
  while (in >> row >> name) names[row] = name;
  return names;
}

// Whether a path ending at `end` reaches the goal: within 1e-9 of the distance between the poses
// (at least 1e-9), but never more than a thousandth of that distance, so that a path ending 1e-9
// from a goal 1e-9 away misses it; and the heading to 1e-12 radians, so that a heading 1e-9 off
// is missed too.
bool reaches(const CarPose& end, const CarPose& from, const CarPose& to) {
  const double d = std::hypot(to.x - from.x, to.y - from.y);
  const double allowed = d > 0 ? std::min(1e-9 * std::max(1.0, d), 1e-3 * d) : 1e-9;
  const double heading = std::abs(std::remainder(end.theta - to.theta, 2 * M_PI));
  return std::hypot(end.x - to.x, end.y - to.y) <= allowed && heading <= 1e-12;
}

// Compares every row; returns the names of the rows where OMPL's path misses its goal.
template <class Shortest>
std::set<std::string> compare_with_ompl(const std::string& file, Shortest shortest) {
  const std::vector<ReferenceRow> rows = read_reference(file);
  EXPECT_EQ(rows.size(), 10536u) << file;
  const auto names = case_names();
  std::set<std::string> ompl_misses;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ReferenceRow& r = rows[i];
    const std::string name = names.count(i) ? names.at(i) : "random " + std::to_string(i);
    const SteeringPath path = shortest(r.from, r.to, r.radius);
    EXPECT_TRUE(reaches(end_pose(path, r.from, r.radius), r.from, r.to)) << file << " row " << i << " " << name;
    if (!reaches(r.ompl_end, r.from, r.to)) {
      ompl_misses.insert(name);
      continue;
    }
    EXPECT_NEAR(path.length(), r.length, 1e-9 * std::max(1.0, r.length))
        << file << " row " << i << " " << name << " " << path.word;
  }
  return ompl_misses;
}

// The cases where OMPL's Dubins path misses its goal, for each radius of steering_cases.txt: a goal
// 1e-9 behind, to the left or to the right with the same heading (0 or 0.7 rad), and a turn of
// +-1e-9 rad (or across the -pi/pi seam) on the spot — each answered by OMPL with a straight of
// 1e-9 or nothing, where the car must loop.
std::set<std::string> where_ompl_dubins_misses() {
  std::set<std::string> names;
  for (const char* radius : {"r0.25", "r1", "r7.5"}) {
    for (const char* side : {"behind", "left", "right"})
      for (const char* heading : {"h0", "h0.7"})
        names.insert(std::string("tiny_") + side + "_same_" + heading + "_" + radius);
    for (const char* turn : {"plus", "minus"}) names.insert(std::string("tiny_turn_") + turn + "_" + radius);
    names.insert(std::string("tiny_seam_turn_") + radius);
  }
  return names;
}

TEST(SteeringAgainstOmpl, DubinsLengthsAgreeWhereOmplReachesTheGoal) {
  EXPECT_EQ(compare_with_ompl("ompl_dubins.csv", shortest_dubins_path), where_ompl_dubins_misses());
}

// A row of dubins_extended.csv: a case where OMPL's Dubins path misses its goal, and the length of
// the shortest path that reaches it, in extended precision (the word is not read: ties, such as
// LSL/RSR around a loop, may be answered by either).
struct ExtendedRow {
  std::string name;
  CarPose from, to;
  double radius, length;
};

std::vector<ExtendedRow> read_extended(const std::string& file) {
  std::ifstream in(reference_file(file));
  EXPECT_TRUE(in) << reference_file(file);
  std::vector<ExtendedRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("name,", 0) == 0) continue;  // the comment and the header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    ExtendedRow r;
    fields >> r.name >> r.from.x >> r.from.y >> r.from.theta >> r.to.x >> r.to.y >> r.to.theta >> r.radius >> r.length;
    EXPECT_FALSE(fields.fail()) << file << ": " << line;
    rows.push_back(r);
  }
  return rows;
}

// Where OMPL's length is no reference, the shortest path that reaches the goal is: every such
// case has its row (and no other case does), so none goes unchecked.
TEST(SteeringAgainstExtendedPrecision, DubinsLengthsWhereOmplMissesItsGoal) {
  const std::set<std::string> misses = where_ompl_dubins_misses();
  std::set<std::string> named;
  for (const ExtendedRow& r : read_extended("dubins_extended.csv")) {
    EXPECT_TRUE(misses.count(r.name)) << r.name << " is not a case where OMPL misses its goal";
    EXPECT_TRUE(named.insert(r.name).second) << r.name << " twice";
    const SteeringPath path = shortest_dubins_path(r.from, r.to, r.radius);
    EXPECT_TRUE(reaches(end_pose(path, r.from, r.radius), r.from, r.to)) << r.name << " " << path.word;
    // 1e-12, not 1e-9: on a turn of 1e-9 rad on the spot the next-best word is only 2R·1e-9 longer.
    EXPECT_NEAR(path.length(), r.length, 1e-12 * std::max(1.0, r.length)) << r.name << " " << path.word;
  }
  EXPECT_EQ(named, misses);
}

TEST(SteeringAgainstOmpl, ReedsSheppLengthsAgreeWhereOmplReachesTheGoal) {
  // OMPL's Reeds–Shepp paths reach every goal of the set.
  EXPECT_EQ(compare_with_ompl("ompl_reeds_shepp.csv", shortest_reeds_shepp_path), (std::set<std::string>{}));
}

}  // namespace
}  // namespace polyplan
