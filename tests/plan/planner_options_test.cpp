// roadmaps/planner_options: an options struct described once, set from text by name, listed with
// its defaults; every refusal names the planner, the option and the value.
#include <polyplan/plan/planner_options.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace polyplan {
namespace {

enum class Shape { round, square };

struct Options {
  std::size_t cells = 100;
  int offset = -2;
  double step = 0.5;
  bool wrap = true;
  std::string label = "none";
  Shape shape = Shape::round;
  SearchOptions search;
};

OptionTable<Options> table() {
  OptionTable<Options> t;
  t.add("cells", &Options::cells, "cells per side")
      .add("offset", &Options::offset, "an offset")
      .add("step", &Options::step, "a step")
      .add("wrap", &Options::wrap, "wraps round")
      .add("label", &Options::label, "a label")
      .add("shape", &Options::shape, "a shape",
           std::vector<std::pair<std::string, Shape>>{{"round", Shape::round}, {"square", Shape::square}});
  add_search_options(t, &Options::search);
  return t;
}

std::string refusal(const OptionValues& values) {
  try {
    table().parse(values, "demo");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(OptionTable, ListsEveryOptionWithItsKindAndDefault) {
  const std::vector<OptionInfo> info = table().info();
  ASSERT_EQ(info.size(), 9u);
  const auto at = [&](std::size_t i) { return info[i].name + " [" + info[i].kind + "] = " + info[i].default_value; };
  EXPECT_EQ(at(0), "cells [whole number in [0, inf)] = 100");
  EXPECT_EQ(at(1), "offset [whole number in (-inf, inf)] = -2");
  EXPECT_EQ(at(2), "step [number in (-inf, inf)] = 0.5");
  EXPECT_EQ(at(3), "wrap [true or false] = true");
  EXPECT_EQ(at(4), "label [text] = none");
  EXPECT_EQ(at(5), "shape [round|square] = round");
  EXPECT_EQ(at(6), "search [astar|dijkstra|bfs|dfs|greedy|wastar] = astar");
  EXPECT_EQ(at(7), "weight [number in [1, inf)] = 1");
  EXPECT_EQ(at(8), "reopen [true or false] = false");
  EXPECT_TRUE(info[3].flag);
  EXPECT_TRUE(info[8].flag);
  EXPECT_FALSE(info[0].flag);
  EXPECT_FALSE(info[5].flag);
}

TEST(OptionTable, SetsEveryKindFromText) {
  const Options o = table().parse({{"cells", "40"},
                                   {"offset", "-7"},
                                   {"step", "2.5e-1"},
                                   {"wrap", "no"},
                                   {"label", "a=b"},
                                   {"shape", "square"},
                                   {"search", "wastar"},
                                   {"weight", "3"},
                                   {"reopen", "true"}},
                                  "demo");
  EXPECT_EQ(o.cells, 40u);
  EXPECT_EQ(o.offset, -7);
  EXPECT_EQ(o.step, 0.25);
  EXPECT_FALSE(o.wrap);
  EXPECT_EQ(o.label, "a=b");
  EXPECT_EQ(o.shape, Shape::square);
  EXPECT_EQ(o.search.algorithm, Search::wastar);
  EXPECT_EQ(o.search.weight, 3.0);
  EXPECT_TRUE(o.search.reopen);
  EXPECT_FALSE(table().parse({}, "demo").search.reopen);
  // Unset options keep their defaults; later values replace earlier ones.
  const Options d = table().parse({{"cells", "1"}, {"cells", "2"}}, "demo");
  EXPECT_EQ(d.cells, 2u);
  EXPECT_EQ(d.step, 0.5);
  for (const char* yes : {"true", "yes", "on", "1"}) EXPECT_TRUE(table().parse({{"wrap", yes}}, "demo").wrap) << yes;
}

TEST(OptionTable, RefusalsNameThePlannerTheOptionAndTheValue) {
  EXPECT_EQ(refusal({{"cells", "4x"}}), "planner demo: option cells=4x: expected a whole number");
  EXPECT_EQ(refusal({{"cells", ""}}), "planner demo: option cells=: expected a whole number");
  EXPECT_EQ(refusal({{"cells", "-1"}}), "planner demo: option cells=-1: expected a whole number >= 0");
  EXPECT_EQ(refusal({{"offset", "99999999999"}}), "planner demo: option offset=99999999999: out of range");
  EXPECT_EQ(refusal({{"step", "nan"}}), "planner demo: option step=nan: expected a finite number");
  EXPECT_EQ(refusal({{"step", "1e999"}}), "planner demo: option step=1e999: expected a finite number");
  EXPECT_EQ(refusal({{"wrap", "maybe"}}), "planner demo: option wrap=maybe: expected true or false");
  EXPECT_EQ(refusal({{"shape", "oval"}}), "planner demo: option shape=oval: expected one of round|square");
  EXPECT_EQ(refusal({{"search", "teleport"}}),
            "planner demo: option search=teleport: expected one of astar|dijkstra|bfs|dfs|greedy|wastar");
  EXPECT_EQ(refusal({{"weight", "0.9"}}), "planner demo: option weight=0.9: expected a number in [1, inf)");
  EXPECT_EQ(refusal({{"reopen", "sometimes"}}), "planner demo: option reopen=sometimes: expected true or false");
  EXPECT_EQ(refusal({{"colour", "red"}}),
            "planner demo: option colour=red: no such option (its options: cells, offset, step, wrap, label, shape, "
            "search, weight, reopen)");
  EXPECT_EQ(OptionTable<Options>().parse({}, "empty").cells, 100u);
  try {
    OptionTable<Options>().parse({{"cells", "1"}}, "empty");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "planner empty: option cells=1: no such option (it takes none)");
  }
}

TEST(OptionTable, NumbersShowAsTheShortestTextThatReadsBack) {
  EXPECT_EQ(detail::show_number(0.1), "0.1");
  EXPECT_EQ(detail::show_number(5), "5");
  EXPECT_EQ(detail::show_number(1e-7), "1e-07");
  EXPECT_EQ(*detail::parse_real_number(detail::show_number(2.0 / 3)), 2.0 / 3);
}

}  // namespace
}  // namespace polyplan
