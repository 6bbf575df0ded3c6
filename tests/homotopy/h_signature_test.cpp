// Words of paths: the commutator round two holes is not trivial (homotopy, not homology), going
// back and forth changes nothing, a path's word is the product of its segments', and 200 holes
// give 200 distinct loop words.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/homotopy/h_signature.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace polyplan {
namespace {

Ring square(Rational x, Rational y, Rational half) {
  return {{x - half, y - half}, {x + half, y - half}, {x + half, y + half}, {x - half, y + half}};
}

World world_of(std::vector<Ring> squares) {
  World world;
  world.bounds = Bounds{-100, -100, 100, 100};
  for (Ring& s : squares) {
    world.obstacle_names.push_back("obstacles[" + std::to_string(world.obstacles.size()) + "]");
    world.obstacles.push_back(PolygonWithHoles{std::move(s), {}});
  }
  return world;
}

// A loop round the box [x0, x1] × [y0, y1], anticlockwise from its lower left corner.
std::vector<ExactPoint> loop(Rational x0, Rational y0, Rational x1, Rational y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
}

TEST(Words, ReduceInTheFreeGroupAndPrint) {
  Word w{1, 2};
  multiply(w, {-2, -1, 3});
  EXPECT_EQ(w, Word{3});
  EXPECT_EQ(word_text({1, -2, 1}), "t1 t2' t1");
  Word product{1, -2};
  multiply(product, inverse(product));
  EXPECT_TRUE(product.empty());
}

TEST(Words, TheCommutatorRoundTwoHolesIsNotTrivial) {
  const CSpace cspace(world_of({square(0, 0, 1), square(10, 0, 1)}));
  const HSignature h(cspace);
  ASSERT_EQ(h.rays().size(), 2u);
  const auto a = loop(-3, -3, 3, 3), b = loop(7, -3, 13, 3);  // round hole 1 only, round hole 2 only
  const Word wa = h.polyline(a), wb = h.polyline(b);
  ASSERT_EQ(wa.size(), 1u);
  ASSERT_EQ(wb.size(), 1u);
  EXPECT_NE(std::abs(wa[0]), std::abs(wb[0]));
  // a · b · a⁻¹ · b⁻¹ from a common point: go to b's corner and back along the same line.
  std::vector<ExactPoint> commutator = a;
  const std::vector<ExactPoint> to_b{{-3, -3}, {7, -3}}, from_b{{7, -3}, {-3, -3}};
  const auto append = [&](const std::vector<ExactPoint>& part) {
    commutator.insert(commutator.end(), part.begin() + 1, part.end());
  };
  append(to_b), append(b), append(from_b);
  std::vector<ExactPoint> a_back(a.rbegin(), a.rend()), b_back(b.rbegin(), b.rend());
  append(a_back), append(to_b), append(b_back), append(from_b);
  const Word w = h.polyline(commutator);
  EXPECT_EQ(w.size(), 4u) << word_text(w);
  // Its winding number round each hole is 0: the letters of each hole sum to nothing.
  int one = 0, two = 0;
  for (const int letter : w) (std::abs(letter) == std::abs(wa[0]) ? one : two) += letter > 0 ? 1 : -1;
  EXPECT_EQ(one, 0);
  EXPECT_EQ(two, 0);
}

TEST(Words, BackAndForthChangesNothingAndSegmentsMultiply) {
  const CSpace cspace(world_of({square(0, 0, 1), square(5, 5, 1)}));
  const HSignature h(cspace);
  const std::vector<ExactPoint> path{{-4, -4}, {-4, 4}, {3, 4}, {3, 8}, {8, 8}};
  std::vector<ExactPoint> wiggle{{-4, -4}, {-4, 4}, {3, 4}, {-4, 4}, {3, 4}, {3, 8}, {8, 8}};
  EXPECT_EQ(h.polyline(wiggle), h.polyline(path));
  Word product;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) multiply(product, h.segment(path[i], path[i + 1]));
  EXPECT_EQ(product, h.polyline(path));
  // A path vertex exactly on a ray's line (x = the ray's x) counts on its right, both ways.
  const Rational rx = h.rays()[0].origin.x;
  const std::vector<ExactPoint> through{{-4, 3}, {rx, 3}, {4, 3}}, straight{{-4, 3}, {4, 3}};
  EXPECT_EQ(h.polyline(through), h.polyline(straight));
  EXPECT_EQ(h.polyline(straight).size(), 1u);
}

TEST(Words, TwoHundredHolesGiveTwoHundredLoopWords) {
  std::vector<Ring> squares;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j) squares.push_back(square(-95 + 10 * i, -95 + 10 * j, 1));
  const CSpace cspace(world_of(squares));
  const HSignature h(cspace);
  ASSERT_EQ(h.rays().size(), 200u);
  std::set<Word> words;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j) {
      const Rational x = -95 + 10 * i, y = -95 + 10 * j;
      const Word w = h.polyline(loop(x - 3, y - 3, x + 3, y + 3));
      EXPECT_FALSE(w.empty());
      words.insert(w);
    }
  EXPECT_EQ(words.size(), 200u);
}

}  // namespace
}  // namespace polyplan
