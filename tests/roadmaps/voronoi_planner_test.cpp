// The maximum-clearance planner against an independent reference: the best clearance r* found by
// bisection on r with CGAL's offsets — the C-obstacles grown by r (approximated_offset_2, circular
// arcs, error 1e-10), the walls moved in by r, and whether start and goal stay in one component of
// what is left — on hand-made worlds, the shipped worlds and random ones.
#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/roadmap_facts.hpp>
#include <polyplan/roadmaps/voronoi_planner.hpp>
#include "movingai_fixtures.hpp"
#include "world_fixtures.hpp"

#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/approximated_offset_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

using namespace polyplan;
using polyplan::test::between;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

using Traits = CGAL::Gps_circle_segment_traits_2<detail::Kernel>;
using OffsetSet = CGAL::General_polygon_set_2<Traits>;

// The exact distance from p to the free space's boundary (C-obstacles and walls), rounded once.
double exact_clearance(const CSpace& c, const ExactPoint& p) {
  detail::FT nearest = -1;
  auto consider = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const detail::FT d =
          CGAL::squared_distance(detail::to_point(p), detail::Segment(detail::to_point(ring[i]),
                                                                      detail::to_point(ring[(i + 1) % ring.size()])));
      if (nearest < 0 || d < nearest) nearest = d;
    }
  };
  for (const FreeComponent& component : c.free_components()) {
    consider(component.outer);
    for (const Ring& h : component.holes) consider(h);
  }
  return std::sqrt(CGAL::to_double(nearest));
}

Traits::Polygon_2 rectangle(const detail::FT& x0, const detail::FT& y0, const detail::FT& x1, const detail::FT& y1) {
  const detail::Point corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  Traits::Polygon_2 polygon;
  for (int i = 0; i < 4; ++i) polygon.push_back(Traits::X_monotone_curve_2(corners[i], corners[(i + 1) % 4]));
  return polygon;
}

// Whether start and goal lie in one component of {p : distance(p, C-obstacles and walls) >= r}.
bool joined_at(const CSpace& c, const ExactPoint& start, const ExactPoint& goal, double r) {
  const detail::FT radius(r);
  OffsetSet grown;
  for (const PolygonWithHoles& o : c.cobstacles())
    grown.join(CGAL::approximated_offset_2(detail::to_polygon(o), radius, 1e-10));
  OffsetSet clear;
  if (const auto& box = c.reference_box()) {
    const detail::FT x0 = detail::to_ft(box->xmin) + radius, y0 = detail::to_ft(box->ymin) + radius;
    const detail::FT x1 = detail::to_ft(box->xmax) - radius, y1 = detail::to_ft(box->ymax) - radius;
    if (!(x0 < x1 && y0 < y1)) return false;
    clear = OffsetSet(rectangle(x0, y0, x1, y1));
    clear.difference(grown);
  } else {
    clear = grown;
    clear.complement();
  }
  std::vector<Traits::Polygon_with_holes_2> parts;
  clear.polygons_with_holes(std::back_inserter(parts));
  const Traits::Point_2 s(detail::to_ft(start.x), detail::to_ft(start.y)),
      g(detail::to_ft(goal.x), detail::to_ft(goal.y));
  for (const auto& part : parts) {
    const OffsetSet one(part);
    if (one.oriented_side(s) != CGAL::ON_NEGATIVE_SIDE && one.oriented_side(g) != CGAL::ON_NEGATIVE_SIDE) return true;
  }
  return false;
}

// r* by bisection to 1e-7, capped by the clearance of start and goal; nullopt when they lie in
// different components of the exact free space (no clearance joins them).
std::optional<double> best_clearance(const CSpace& c, const ExactPoint& start, const ExactPoint& goal) {
  const auto a = c.locate(start).components, b = c.locate(goal).components;
  if (std::none_of(a.begin(), a.end(), [&](std::size_t k) { return std::find(b.begin(), b.end(), k) != b.end(); }))
    return std::nullopt;
  const double cap = std::min(exact_clearance(c, start), exact_clearance(c, goal));
  if (joined_at(c, start, goal, cap)) return cap;
  double joined = 0, apart = cap;
  while (apart - joined > 1e-7) {
    const double middle = (joined + apart) / 2;
    (joined_at(c, start, goal, middle) ? joined : apart) = middle;
  }
  return joined;
}

void expect_best_clearance(const CSpace& c, const Query& q) {
  SCOPED_TRACE(to_string(q.start) + " to " + to_string(q.goal));
  VoronoiPlanner planner(c);
  const auto report = planner.plan(q);
  const auto best = best_clearance(c, q.start, q.goal);
  ASSERT_EQ(report.found, best.has_value()) << report.why_not;
  if (!report.found) return;
  EXPECT_TRUE(check_path(c, report.path).valid);
  EXPECT_NEAR(report.bottleneck.value().clearance, *best, 1e-6);
}

TEST(VoronoiPlanner, AroundASquareTheWidestPassageIsHalfItsWidth) {
  // Passages of width 4 above and below the square [4, 6]^2 in a 10 x 10 box: r* = 2, and the
  // start (2, 5) and goal (8, 5) are 2 from everything themselves.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})"));
  VoronoiPlanner planner(c);
  const auto report = planner.plan(between(pt("2", "5"), pt("8", "5")));
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_NEAR(report.bottleneck.value().clearance, 2, 1e-7);
  EXPECT_NEAR(report.facts.at(VoronoiFacts::bottleneck), 2, 1e-12);
  EXPECT_TRUE(check_path(c, report.path).valid);
  // The bottleneck named is a point of the path that is that close to the boundary.
  const ExactPoint at{Rational(report.bottleneck.value().x), Rational(report.bottleneck.value().y)};
  EXPECT_NEAR(exact_clearance(c, at), 2, 1e-7);
}

TEST(VoronoiPlanner, ThroughAGapTheClearanceIsHalfTheGap) {
  // A band across the box with a gap of width 1 at x in [4.5, 5.5]: r* = 1/2.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[0, 4], [4.5, 4], [4.5, 6], [0, 6]],
      [[5.5, 4], [10, 4], [10, 6], [5.5, 6]]]})"));
  VoronoiPlanner planner(c);
  const auto report = planner.plan(between(pt("2", "2"), pt("8", "8")));
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_NEAR(report.bottleneck.value().clearance, 0.5, 1e-7);
  EXPECT_NEAR(report.bottleneck.value().x, 5, 1e-6);
  expect_best_clearance(c, between(pt("2", "2"), pt("8", "8")));
}

TEST(VoronoiPlanner, APinchPointIsNoPassage) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [
      [[0, 4], [4, 4], [5, 5], [4, 6], [0, 6]], [[10, 4], [10, 6], [6, 6], [5, 5], [6, 4]]]})"));
  VoronoiPlanner planner(c);
  const auto report = planner.plan(between(pt("5", "1"), pt("5", "9")));
  EXPECT_FALSE(report.found);
  EXPECT_EQ(report.why_not, "start and goal lie in different components of the free space");
}

TEST(VoronoiPlanner, AStartOnTheBoundaryHasNoClearanceToGive) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})"));
  VoronoiPlanner planner(c);
  const auto report = planner.plan(between(pt("4", "5"), pt("8", "5")));
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_EQ(report.bottleneck.value().clearance, 0);
  EXPECT_TRUE(check_path(c, report.path).valid);
}

TEST(VoronoiPlanner, APassageNarrowerThanDoublesResolveIsTakenExactly) {
  // decimal.json's slit of 1e-17 between two obstacles: closed in the diagram's doubles, open in
  // the exact free space.
  const World world = read_world(test::data_file("worlds/decimal.json"));
  const CSpace c(world);
  VoronoiPlanner planner(c);
  const auto report = planner.plan(world.queries[1]);
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_TRUE(report.facts.at(VoronoiFacts::narrows));
  EXPECT_TRUE(check_path(c, report.path).valid);
  EXPECT_LT(report.bottleneck.value().clearance, 1e-15);
}

TEST(VoronoiPlanner, OnTheShippedWorldsTheClearanceIsTheBestPossible) {
  for (const char* name : {"corridor_wide", "wkt_obstacles", "seed004", "office", "touching_corners"}) {
    SCOPED_TRACE(name);
    const World world = read_world(test::data_file(std::string("worlds/") + name + ".json"));
    const CSpace c(world);
    for (const Query& q : world.queries)
      if (!c.query_not_free(q)) expect_best_clearance(c, q);
  }
}

// A world of random triangles with decimal corners in a 10 x 10 box (the trapezoid test's kind).
std::string random_world(std::mt19937& rng, bool bounded) {
  std::uniform_int_distribution<int> coordinate(0, 1000), offset(-150, 150);
  std::ostringstream json;
  json << "{" << (bounded ? R"("bounds": [0, 0, 10, 10], )" : "") << R"("obstacles": [)";
  for (int t = 0; t < 6; ++t) {
    const int cx = coordinate(rng), cy = coordinate(rng);
    json << (t ? ", " : "") << "[";
    for (int k = 0; k < 3; ++k)
      json << (k ? ", " : "") << "[" << std::clamp(cx + offset(rng), 0, 1000) / 100.0 << ", "
           << std::clamp(cy + offset(rng), 0, 1000) / 100.0 << "]";
    json << "]";
  }
  json << "]}";
  return json.str();
}

TEST(VoronoiPlanner, OnRandomWorldsTheClearanceIsTheBestPossible) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coordinate(0, 1000);
  int compared = 0;
  for (int w = 0; w < 12; ++w) {
    std::optional<World> world;
    try {
      world = world_from(random_world(rng, w % 4 != 3));
    } catch (const InputError&) {
      continue;
    }
    const CSpace c(*world);
    for (int q = 0; q < 3; ++q) {
      const Query query = between({Rational(coordinate(rng)) / 100, Rational(coordinate(rng)) / 100},
                                  {Rational(coordinate(rng)) / 100, Rational(coordinate(rng)) / 100});
      if (c.query_not_free(query)) continue;
      expect_best_clearance(c, query);
      ++compared;
    }
  }
  EXPECT_GT(compared, 20);
}

TEST(VoronoiPlannerOnMovingAi, ArenaAnswersEveryScenario) {
  test::expect_answers_to_the_scenarios<VoronoiPlanner>("arena", 1, 150);
}
TEST(VoronoiPlannerOnMovingAi, Den312dAnswersEveryScenario) {
  test::expect_answers_to_the_scenarios<VoronoiPlanner>("den312d", 1, 300);
}
TEST(VoronoiPlannerOnMovingAi, Lak303dAnswersASample) {
  test::expect_answers_to_the_scenarios<VoronoiPlanner>("lak303d", 10, 100);
}

}  // namespace
