// draw/report_pictures: the front door's reports drawn whatever their space — a world's in one
// picture, an arm's one per report with its title — and reports of two spaces refused.
#include <polyplan/draw/report_pictures.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace polyplan {
namespace {

Problem read(const std::string& path) {
  std::vector<std::string> warnings;
  return Problem::read(std::string(POLYPLAN_SOURCE_DIR) + "/data/" + path, &warnings);
}

TEST(Report, PicturesAreDrawnForEveryKindOfProblem) {
  const Problem world = read("worlds/seed004.json");
  const Report plan = make_planner("raster", world)->plan(0, QueryOptions{true});
  const auto world_pictures = draw_reports(world, {&plan, &plan});
  ASSERT_EQ(world_pictures.size(), 1u);  // a world: every report in one picture
  EXPECT_NE(world_pictures.front().drawing.str().find("<svg"), std::string::npos);

  const Problem arm = read("arms/two_link_points.json");
  const auto grid = make_planner("grid", arm);
  const Report easy = grid->plan(0), hard = grid->plan(2);
  const auto arm_pictures = draw_reports(arm, {&easy, &hard}, {true, 3, " · resolution 5"});
  ASSERT_EQ(arm_pictures.size(), 2u);  // an arm: one picture per report
  EXPECT_EQ(arm_pictures[1].query, "hard");
  EXPECT_NE(arm_pictures[0].drawing.str().find("two_link_points.json · easy · grid · resolution 5"), std::string::npos);
  EXPECT_THROW(draw_reports(world, {&plan, &easy}), InputError);  // reports of two spaces
}

}  // namespace
}  // namespace polyplan
