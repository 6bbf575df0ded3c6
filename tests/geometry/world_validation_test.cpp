// validate_world (geometry/world_validation.cpp) on worlds built in code, as a program that does
// not read files builds them: every problem is one exact message naming world.source and the
// object (as world.obstacle_names names it); valid rings come back oriented and without repeats.
#include <polyplan/geometry/world_validation.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polyplan;
using polyplan::test::input_error_of;
using polyplan::test::pt;
using polyplan::test::signed_area;

namespace {

Ring rectangle(const char* x0, const char* y0, const char* x1, const char* y1) {
  return {pt(x0, y0), pt(x1, y0), pt(x1, y1), pt(x0, y1)};
}

// A world built in code, its obstacles named as a world file would name them.
World built(std::vector<PolygonWithHoles> obstacles) {
  World world;
  world.source = "built-in world";
  world.obstacles = std::move(obstacles);
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    world.obstacle_names.push_back("obstacles[" + std::to_string(i) + "]");
  return world;
}

std::string problem_of(World world) {
  return input_error_of([&] { validate_world(world); });
}

}  // namespace

TEST(ValidateWorld, NormalisesOrientationSilently) {
  // Clockwise outer boundary, counter-clockwise hole, clockwise robot part: all turned around.
  World w = built({{{pt("0", "0"), pt("0", "6"), pt("6", "6"), pt("6", "0")}, {rectangle("2", "2", "4", "4")}}});
  w.robot.parts = {{pt("0", "0"), pt("0", "1"), pt("1", "0")}};
  validate_world(w);
  EXPECT_EQ(w.obstacles[0].outer, (Ring{pt("6", "0"), pt("6", "6"), pt("0", "6"), pt("0", "0")}));
  EXPECT_EQ(w.obstacles[0].holes[0], (Ring{pt("2", "4"), pt("4", "4"), pt("4", "2"), pt("2", "2")}));
  EXPECT_EQ(w.robot.parts[0], (Ring{pt("1", "0"), pt("0", "1"), pt("0", "0")}));
  EXPECT_EQ(signed_area(w.obstacles[0].outer), Rational(36));
  EXPECT_EQ(signed_area(w.obstacles[0].holes[0]), Rational(-4));
  EXPECT_EQ(signed_area(w.robot.parts[0]), Rational(1, 2));
}

TEST(ValidateWorld, KeepsRingsThatAreAlreadyOriented) {
  World w = built({{rectangle("0", "0", "1", "1"), {}}});
  validate_world(w);
  EXPECT_EQ(w.obstacles[0].outer, rectangle("0", "0", "1", "1"));
}

TEST(ValidateWorld, DropsRepeatedVertices) {
  // A repeated vertex and a closing copy of the first carry no shape.
  World w = built({{{pt("0", "0"), pt("1", "0"), pt("1", "0"), pt("1", "1"), pt("0", "0")}, {}}});
  validate_world(w);
  EXPECT_EQ(w.obstacles[0].outer, (Ring{pt("0", "0"), pt("1", "0"), pt("1", "1")}));
}

TEST(ValidateWorld, NamesTheCrossingEdges) {
  EXPECT_EQ(problem_of(built(
                {{{pt("0", "0"), pt("1", "0")}, {}}, {{pt("0", "0"), pt("2", "2"), pt("2", "0"), pt("0", "2")}, {}}})),
            "built-in world: obstacles[0]: fewer than 3 distinct vertices");
  EXPECT_EQ(problem_of(built({{{pt("0", "0"), pt("2", "2"), pt("2", "0"), pt("0", "2")}, {}}})),
            "built-in world: obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 2] crosses edge 2 [2, 0]-[0, 2]");
}

TEST(ValidateWorld, SpikeIsNotSimple) {
  // Edges 0 and 1 fold back over each other along y = 0.
  EXPECT_EQ(
      problem_of(built({{{pt("0", "0"), pt("2", "0"), pt("1", "0"), pt("1", "1")}, {}}})),
      "built-in world: obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 0] folds back over edge 1 [2, 0]-[1, 0]");
}

TEST(ValidateWorld, ThreeEqualVerticesAreFewerThanThree) {
  EXPECT_EQ(problem_of(built({{{pt("1", "1"), pt("1", "1"), pt("1", "1")}, {}}})),
            "built-in world: obstacles[0]: fewer than 3 distinct vertices");
}

TEST(ValidateWorld, CollinearPolygonHasZeroArea) {
  // Named as world.obstacle_names says: here, a polygon of a WKT file.
  World w = built({{rectangle("0", "0", "1", "1"), {}}, {{pt("0", "0"), pt("1/3", "1"), pt("1", "3")}, {}}});
  w.obstacle_names[1] = "obstacles.wkt polygon 1";
  EXPECT_EQ(problem_of(w), "built-in world: obstacles.wkt polygon 1: zero area (all vertices on one line)");
}

TEST(ValidateWorld, HoleOutsideItsOuterBoundary) {
  EXPECT_EQ(problem_of(built({{rectangle("0", "0", "6", "6"), {rectangle("7", "7", "8", "8")}}})),
            "built-in world: obstacles[0] hole 0: not inside the outer boundary of obstacles[0]");
}

TEST(ValidateWorld, HoleCrossingItsOuterBoundary) {
  EXPECT_EQ(problem_of(built(
                {{rectangle("0", "0", "6", "6"), {rectangle("1", "1", "2", "2"), rectangle("4", "4", "8", "5")}}})),
            "built-in world: obstacles[0] hole 1: not inside the outer boundary of obstacles[0]");
}

TEST(ValidateWorld, HoleTouchingItsOuterBoundaryFromInsideIsAccepted) {
  // Regularized: a hole may touch the outer boundary, here at the vertex (0, 3).
  World w = built({{rectangle("0", "0", "6", "6"), {{pt("0", "3"), pt("2", "2"), pt("2", "4")}}}});
  EXPECT_EQ(problem_of(w), "no InputError");
}

TEST(ValidateWorld, BadHoleIsNamedByItsNumber) {
  EXPECT_EQ(problem_of(built(
                {{rectangle("0", "0", "6", "6"), {rectangle("1", "1", "2", "2"), {pt("3", "3"), pt("4", "4")}}}})),
            "built-in world: obstacles[0] hole 1: fewer than 3 distinct vertices");
}

TEST(ValidateWorld, InvertedOrEmptyBounds) {
  World inverted = built({});
  inverted.bounds = Bounds{4, 0, Rational(1, 2), 4};
  EXPECT_EQ(problem_of(inverted),
            "built-in world: bounds: empty or inverted: [4, 0, 1/2, 4] needs xmin < xmax and ymin < ymax");
  World flat = built({});
  flat.bounds = Bounds{0, 2, 4, 2};
  EXPECT_EQ(problem_of(flat),
            "built-in world: bounds: empty or inverted: [0, 2, 4, 2] needs xmin < xmax and ymin < ymax");
}

TEST(ValidateWorld, BoundsAreCheckedBeforeObstacles) {
  World w = built({{{pt("0", "0"), pt("1", "0")}, {}}});
  w.bounds = Bounds{1, 1, 0, 0};
  EXPECT_EQ(problem_of(w), "built-in world: bounds: empty or inverted: [1, 1, 0, 0] needs xmin < xmax and ymin < ymax");
}

TEST(ValidateWorld, RobotPartThatIsABowTie) {
  World w = built({{rectangle("0", "0", "1", "1"), {}}});
  w.robot.parts = {rectangle("0", "0", "1", "1"), {pt("0", "0"), pt("1", "1"), pt("1", "0"), pt("0", "1")}};
  EXPECT_EQ(problem_of(w),
            "built-in world: robot.parts[1]: self-intersecting: edge 0 [0, 0]-[1, 1] crosses edge 2 [1, 0]-[0, 1]");
}

TEST(ValidateWorld, ValidWorldPassesUnchangedButForOrientation) {
  World w = built({{rectangle("1", "1", "2", "2"), {}}});
  w.bounds = Bounds{0, 0, 4, 4};
  w.robot.parts = {rectangle("-1/2", "-1/2", "1/2", "1/2")};
  const World before = w;
  validate_world(w);
  EXPECT_EQ(w.obstacles[0].outer, before.obstacles[0].outer);
  EXPECT_EQ(w.robot.parts[0], before.robot.parts[0]);
  EXPECT_EQ(w.source, "built-in world");
}

// Overlapping or nested holes made CGAL's operations answer inconsistently (a path through the
// obstacle between two overlapping holes); now the second hole of the first such pair is named.
TEST(ValidateWorld, HolesThatOverlapOrNestAreRefused) {
  const Ring outer = rectangle("1", "1", "9", "9");
  EXPECT_EQ(problem_of(built({{outer, {rectangle("2", "2", "5", "5"), rectangle("4", "4", "7", "7")}}})),
            "built-in world: obstacles[0] hole 1: overlaps hole 0 (holes may touch but not overlap or nest)");
  EXPECT_EQ(problem_of(built({{outer, {rectangle("2", "2", "8", "8"), rectangle("3", "3", "4", "4")}}})),
            "built-in world: obstacles[0] hole 1: overlaps hole 0 (holes may touch but not overlap or nest)");
  EXPECT_EQ(
      problem_of(built(
          {{outer, {rectangle("2", "2", "3", "3"), rectangle("6", "6", "8", "8"), rectangle("2", "2", "3", "3")}}})),
      "built-in world: obstacles[0] hole 2: overlaps hole 0 (holes may touch but not overlap or nest)");
}

TEST(ValidateWorld, HolesThatTouchEachOtherOrTheOuterBoundaryAreAccepted) {
  const Ring outer = rectangle("1", "1", "9", "9");
  World w =
      built({{outer, {rectangle("2", "2", "5", "5"), rectangle("5", "2", "8", "5"), rectangle("5", "5", "6", "6")}}});
  EXPECT_NO_THROW(validate_world(w));
  World touching_at_a_corner = built({{outer, {{pt("1", "1"), pt("5", "3"), pt("3", "5")}}}});
  EXPECT_NO_THROW(validate_world(touching_at_a_corner));
}

// CGAL kept such a hole filled (a point inside it was located as blocked): a silent wrong answer.
TEST(ValidateWorld, AHoleSharingAnEdgeWithItsOuterBoundaryIsRefused) {
  const std::string problem =
      "shares a boundary segment with the outer boundary of obstacles[0] (zero width there: make the "
      "hole a notch of the outer boundary instead)";
  EXPECT_EQ(problem_of(built({{rectangle("1", "1", "9", "9"), {rectangle("1", "1", "5", "5")}}})),
            "built-in world: obstacles[0] hole 0: " + problem);
  // Part of an edge is enough.
  EXPECT_EQ(problem_of(built({{rectangle("1", "1", "9", "9"),
                               {rectangle("2", "2", "3", "3"), {pt("4", "1"), pt("6", "1"), pt("5", "3")}}}})),
            "built-in world: obstacles[0] hole 1: " + problem);
}

// The pair of crossing edges was searched among all n² pairs: 27 s for 20,000 vertices. A star
// polygon with two vertices swapped, found among the pairs whose bounding boxes meet.
TEST(ValidateWorld, NamesTheCrossingEdgesOfALargePolygon) {
  const int n = 20000;
  Ring star;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * 3.14159265358979 * i / n, radius = i % 2 ? 150000 : 100000;
    star.push_back(
        {Rational(static_cast<long>(radius * std::cos(angle))), Rational(static_cast<long>(radius * std::sin(angle)))});
  }
  World valid = built({{star, {}}});
  EXPECT_NO_THROW(validate_world(valid));
  std::swap(star[5000], star[5002]);
  const std::string message = problem_of(built({{star, {}}}));
  EXPECT_EQ(message.rfind("built-in world: obstacles[0]: self-intersecting: edge 4999 ", 0), 0u) << message;
}
