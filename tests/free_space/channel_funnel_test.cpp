// The funnel algorithm on channels whose shortest paths are known by hand.
#include <polyplan/free_space/channel_funnel.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::pt;

namespace {

// A vertical portal at x from y0 to y1, crossed rightwards (its upper end on the left hand).
Portal rightwards(const char* x, const char* y0, const char* y1) { return {pt(x, y1), pt(x, y0)}; }
Portal leftwards(const char* x, const char* y0, const char* y1) { return {pt(x, y0), pt(x, y1)}; }

TEST(ChannelFunnel, AStraightChannelIsOneSegment) {
  const auto path = funnel_path(pt("0", "0"), {rightwards("1", "-1", "1"), rightwards("2", "-1", "1")}, pt("3", "0"));
  EXPECT_EQ(path, (std::vector<ExactPoint>{pt("0", "0"), pt("3", "0")}));
}

TEST(ChannelFunnel, NoPortalsIsTheSegment) {
  EXPECT_EQ(funnel_path(pt("0", "0"), {}, pt("1", "1")), (std::vector<ExactPoint>{pt("0", "0"), pt("1", "1")}));
}

TEST(ChannelFunnel, BendsAtThePortalEndsItMustGoAround) {
  // A high gate, then a low one: the path bends at the high gate's lower end and the low gate's
  // upper end.
  const auto path = funnel_path(pt("0", "0"), {rightwards("1", "2", "3"), rightwards("2", "-1", "1/2")}, pt("3", "0"));
  EXPECT_EQ(path, (std::vector<ExactPoint>{pt("0", "0"), pt("1", "2"), pt("2", "1/2"), pt("3", "0")}));
}

TEST(ChannelFunnel, GoesAroundACornerSharedByTwoPortals) {
  // A U-turn around the end (1, 1) of a thin obstacle along y = 1, x < 1: right through the wall
  // below that end, then left through the wall above it. Both walls end at (1, 1).
  const auto path = funnel_path(pt("0", "0"), {rightwards("1", "0", "1"), leftwards("1", "1", "3")}, pt("0", "2"));
  EXPECT_EQ(path, (std::vector<ExactPoint>{pt("0", "0"), pt("1", "1"), pt("0", "2")}));
}

TEST(ChannelFunnel, ATautLineThroughAPortalEndIsNotBent) {
  // The straight line from (0, 0) to (4, 4) grazes the portal end (2, 2): no bend is listed.
  const auto path = funnel_path(pt("0", "0"), {rightwards("2", "2", "5")}, pt("4", "4"));
  EXPECT_EQ(path, (std::vector<ExactPoint>{pt("0", "0"), pt("4", "4")}));
}

TEST(ChannelFunnel, ManyPortalsOnAZigZagBendAtEachInnerCorner) {
  // Alternating narrow gates high and low: the path bends at every gate's inner end.
  std::vector<Portal> gates;
  for (int i = 1; i <= 6; ++i) {
    const std::string x = std::to_string(i);
    gates.push_back(i % 2 ? rightwards(x.c_str(), "4", "5") : rightwards(x.c_str(), "0", "1"));
  }
  const auto path = funnel_path(pt("0", "2.5"), gates, pt("7", "2.5"));
  ASSERT_EQ(path.size(), 8u);
  for (int i = 1; i <= 6; ++i) EXPECT_EQ(path[i], i % 2 ? pt(std::to_string(i), "4") : pt(std::to_string(i), "1"));
}

}  // namespace
