// The Voronoi diagram is the same every time it is built: CGAL's segment Delaunay graph orders its
// faces by memory address, and the diagram numbers sites, edges and vertices by geometry instead,
// so two diagrams of one C-space built in one process (the heap in another state for the second)
// agree to the last bit. The planner's answers are tested in tests/roadmaps/voronoi_planner_test.cpp.
#include <polyplan/free_space/voronoi_diagram.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace polyplan {
namespace {

void expect_same(const VoronoiDiagram& a, const VoronoiDiagram& b) {
  ASSERT_EQ(a.sites().size(), b.sites().size());
  for (std::size_t s = 0; s < a.sites().size(); ++s) {
    EXPECT_EQ(a.sites()[s].a.x, b.sites()[s].a.x);
    EXPECT_EQ(a.sites()[s].a.y, b.sites()[s].a.y);
    EXPECT_EQ(a.sites()[s].b.x, b.sites()[s].b.x);
    EXPECT_EQ(a.sites()[s].b.y, b.sites()[s].b.y);
  }
  ASSERT_EQ(a.vertices().size(), b.vertices().size());
  for (std::size_t v = 0; v < a.vertices().size(); ++v) {
    EXPECT_EQ(a.vertices()[v].at.x, b.vertices()[v].at.x) << "vertex " << v;
    EXPECT_EQ(a.vertices()[v].at.y, b.vertices()[v].at.y) << "vertex " << v;
    EXPECT_EQ(a.vertices()[v].clearance, b.vertices()[v].clearance) << "vertex " << v;
  }
  ASSERT_EQ(a.edges().size(), b.edges().size());
  for (std::size_t e = 0; e < a.edges().size(); ++e) {
    EXPECT_EQ(a.edges()[e].from, b.edges()[e].from) << "edge " << e;
    EXPECT_EQ(a.edges()[e].to, b.edges()[e].to) << "edge " << e;
    EXPECT_EQ(a.edges()[e].clearance, b.edges()[e].clearance) << "edge " << e;
    EXPECT_EQ(a.edges()[e].length, b.edges()[e].length) << "edge " << e;
  }
}

class VoronoiDiagramOfWorld : public ::testing::TestWithParam<std::string> {};

TEST_P(VoronoiDiagramOfWorld, IsTheSameEveryTimeItIsBuilt) {
  const World world = read_world(test::data_file("worlds/" + GetParam() + ".json"));
  const CSpace cspace(world);
  const auto first = std::make_unique<VoronoiDiagram>(cspace, query_points(world));
  // Other allocations between the two builds, so that the second's faces land elsewhere.
  std::vector<std::unique_ptr<VoronoiDiagram>> between;
  for (int i = 0; i < 3; ++i) between.push_back(std::make_unique<VoronoiDiagram>(cspace, query_points(world)));
  between.erase(between.begin());
  const VoronoiDiagram again(cspace, query_points(world));
  expect_same(*first, again);
}

INSTANTIATE_TEST_SUITE_P(ShippedWorlds, VoronoiDiagramOfWorld,
                         ::testing::Values("office", "maze", "seed004", "sphere_world_polygons"));

}  // namespace
}  // namespace polyplan
