// The turn enclosure contains the robot at every angle of the turn: checked on exact rotations at
// many intermediate angles (rational points, so the containment test is exact), for convex and
// non-convex robots, turning either way.
#include <polyplan/geometry/turn_enclosure.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace polyplan {
namespace {

Rational cross(const ExactPoint& o, const ExactPoint& a, const ExactPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// p in the closed convex counter-clockwise polygon, exactly.
bool inside_convex(const Ring& polygon, const ExactPoint& p) {
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (cross(polygon[i], polygon[(i + 1) % polygon.size()], p) < 0) return false;
  return true;
}

bool convex_ccw(const Ring& polygon) {
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (cross(polygon[i], polygon[(i + 1) % polygon.size()], polygon[(i + 2) % polygon.size()]) <= 0) return false;
  return true;
}

// Each enclosure polygon is convex, and at 201 angles of the turn every vertex of the turned robot
// lies in one of them (a convex piece is the hull of its vertices, and its vertices' arcs are what
// its enclosure polygon is built around).
void expect_contains_the_sweep(const Robot& robot, double from, double to) {
  const Robot enclosure = turn_enclosure(robot, exact_rotation(from), exact_rotation(to));
  for (const Ring& polygon : enclosure.parts) EXPECT_TRUE(convex_ccw(polygon));
  for (int k = 0; k <= 200; ++k) {
    const double angle = from + (to - from) * k / 200.0;
    const Robot turned = rotated(robot, exact_rotation(angle));
    for (const Ring& part : turned.parts)
      for (const ExactPoint& v : part) {
        bool in = false;
        for (const Ring& polygon : enclosure.parts) in = in || inside_convex(polygon, v);
        EXPECT_TRUE(in) << "at " << angle << "°, vertex " << to_string(v);
      }
  }
}

Robot robot_of(std::vector<Ring> parts) {
  Robot robot;
  robot.parts = std::move(parts);
  return robot;
}

Robot house() {
  return robot_of({{{Rational(-4), Rational(-2)},
                    {Rational(4), Rational(-2)},
                    {Rational(4), Rational(2)},
                    {Rational(-4), Rational(2)}},
                   {{Rational(-4), Rational(2)}, {Rational(4), Rational(2)}, {Rational(0), Rational(6)}}});
}

TEST(TurnEnclosure, ContainsAConvexRobotAtEveryAngleOfTheTurn) {
  expect_contains_the_sweep(house(), 0, 10);
  expect_contains_the_sweep(house(), 55, 60);
  expect_contains_the_sweep(house(), 10, -35);  // clockwise
  expect_contains_the_sweep(house(), 350, 370);
}

TEST(TurnEnclosure, ContainsTheArcsBeyondTheChords) {
  // A rod's tip on a 10° turn bulges beyond the chord between its two ends by r(1 - cos 5°): the
  // tip's arc at 5° must be inside, which the chord alone would miss.
  const Robot rod = robot_of({{{Rational(-5), Rational(-1, 10)},
                               {Rational(5), Rational(-1, 10)},
                               {Rational(5), Rational(1, 10)},
                               {Rational(-5), Rational(1, 10)}}});
  expect_contains_the_sweep(rod, 0, 10);
  const Robot enclosure = turn_enclosure(rod, exact_rotation(0), exact_rotation(10));
  bool tip_in = false;
  for (const Ring& polygon : enclosure.parts)
    tip_in = tip_in || inside_convex(polygon, rotate({Rational(5), Rational(0)}, exact_rotation(5)));
  EXPECT_TRUE(tip_in);
}

TEST(TurnEnclosure, SplitsANonConvexPartIntoConvexPieces) {
  // An L: its hull would enclose the notch; the enclosure is made of convex pieces instead.
  const Robot l_shape = robot_of({{{Rational(0), Rational(0)},
                                   {Rational(6), Rational(0)},
                                   {Rational(6), Rational(1)},
                                   {Rational(1), Rational(1)},
                                   {Rational(1), Rational(6)},
                                   {Rational(0), Rational(6)}}});
  const Robot enclosure = turn_enclosure(l_shape, exact_rotation(0), exact_rotation(5));
  EXPECT_GE(enclosure.parts.size(), 2u);
  expect_contains_the_sweep(l_shape, 0, 5);
  // The notch's middle stays outside every piece at the start of a small turn.
  for (const Ring& polygon : enclosure.parts) EXPECT_FALSE(inside_convex(polygon, {Rational(3), Rational(3)}));
}

TEST(TurnEnclosure, OfNoTurnIsTheRobotAndOfAHalfTurnIsRefused) {
  const Robot enclosure = turn_enclosure(house(), exact_rotation(30), exact_rotation(30));
  EXPECT_EQ(enclosure.parts, rotated(house(), exact_rotation(30)).parts);
  EXPECT_THROW(turn_enclosure(house(), exact_rotation(0), exact_rotation(180)), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
