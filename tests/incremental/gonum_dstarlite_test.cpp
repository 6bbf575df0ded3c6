// gonum's nine D* Lite cases, run as gonum states them: the grids, starts, goals, vision radii,
// connectivity and edge weights of dynamicDStarLiteTests in gonum's
// graph/path/dynamic/dstarlite_test.go (https://github.com/gonum/gonum, commit
// 0679b21dfc27cd8a31b49fbeeb550b3bd7459e91, BSD-3-Clause, The Gonum Authors), with gonum's own
// expected drives and costs, transcribed into tests/data/gonum_dstarlite/dstarlite_cases.json
// (which says how each of gonum's settings maps onto polyplan's options). Only the data is gonum's.
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/incremental/replan_options.hpp>
#include <polyplan/io/movingai_map.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace polyplan {
namespace {

using nlohmann::json;

json gonum_cases() {
  std::ifstream in(std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/gonum_dstarlite/dstarlite_cases.json");
  return json::parse(in);
}

GridMap grid_of(const json& rows) {
  GridMap map{"gonum", static_cast<int>(rows[0].get<std::string>().size()), static_cast<int>(rows.size()), {}};
  for (const auto& row : rows)
    for (const char c : row.get<std::string>()) map.blocked.push_back(c == '*');
  return map;
}

GridPoint cell_of(const GridMap& map, int id) { return {id % map.width, id / map.width}; }

// The options as the command line and Python give them, through the one option table.
ReplanOptions options_of(const json& c) {
  const auto text = [](const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); };
  ReplanOptions o = replan_option_table().parse_flags({{"sensor", text(c["radius"])},
                                                       {"connectivity", text(c["connectivity"])},
                                                       {"corner-cutting", text(c["corner_cutting"])},
                                                       {"diagonal-cost", text(c["diagonal_cost"])},
                                                       {"known-map", text(c["known_map"])}});
  o.algorithm = ReplanAlgorithm::dstar_lite;
  return o;
}

ReplanResult run(const json& c, ReplanAlgorithm algorithm) {
  GridMap map = grid_of(c["rows"]);
  ReplanOptions o = options_of(c);
  o.algorithm = algorithm;
  if (c.contains("unknown_wall")) {
    // The wall the robot does not know of: missing from the map it knows, there from the first sensing on.
    const int x = c["unknown_wall"][0], y = c["unknown_wall"][1];
    map.blocked[static_cast<std::size_t>(y) * map.width + x] = false;
    o.world_changes = [x, y](std::size_t moves, GridMap& truth) {
      if (moves != 0 || truth.is_blocked(x, y)) return false;
      truth.blocked[static_cast<std::size_t>(y) * truth.width + x] = true;
      return true;
    };
  }
  const GridMap& m = map;
  return drive_through_unknown_map(map, cell_of(m, c["start"]), cell_of(m, c["goal"]), o);
}

TEST(GonumDStarLite, TheNineCasesDriveAsGonumStates) {
  const json cases = gonum_cases()["cases"];
  ASSERT_EQ(cases.size(), 9u);
  for (const auto& c : cases) {
    SCOPED_TRACE(c["name"].get<std::string>());
    const GridMap map = grid_of(c["rows"]);
    const ReplanResult r = run(c, ReplanAlgorithm::dstar_lite);
    ASSERT_TRUE(r.found);
    const json& want = c["drive"];
    ASSERT_EQ(r.traversed.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
      if (!want[i].is_null()) {  // braces: EXPECT_EQ is an if-else of its own
        EXPECT_EQ(r.traversed[i], cell_of(map, want[i])) << "move " << i;
      }
    EXPECT_NEAR(r.grid.in_cells(r.traversed_cost), c["cost"].get<double>(), 1e-9);
  }
}

// The same drives with LPA* and A* from scratch: all three plan the same exact costs and break
// ties alike, so only their work differs.
TEST(GonumDStarLite, LpaStarAndRepeatedAStarDriveTheSame) {
  const json cases = gonum_cases()["cases"];  // kept: a range-for over a part of a temporary reads freed memory
  for (const auto& c : cases) {
    SCOPED_TRACE(c["name"].get<std::string>());
    const ReplanResult d = run(c, ReplanAlgorithm::dstar_lite);
    for (const ReplanAlgorithm a : {ReplanAlgorithm::lpastar, ReplanAlgorithm::astar}) {
      const ReplanResult r = run(c, a);
      EXPECT_EQ(r.traversed, d.traversed) << to_string(a);
      EXPECT_EQ(r.traversed_cost, d.traversed_cost) << to_string(a);
    }
  }
}

TEST(GonumDStarLite, BadGridOptionsAreRefusedNamingTheOption) {
  const auto message = [](const std::string& key, const std::string& value) {
    try {
      replan_option_table().parse_flags({{key, value}});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("connectivity", "6"), "--connectivity 6: expected one of 8|4");
  EXPECT_EQ(message("diagonal-cost", "0.5"),
            "--diagonal-cost 0.5: expected sqrt2 or a number in [1, 1000] (a diagonal move is never cheaper than a "
            "straight one)");
  EXPECT_EQ(message("diagonal-cost", "two"), "--diagonal-cost two: expected sqrt2 or a number of at least 1");
  EXPECT_EQ(message("sensor", "1"),
            "--sensor 1: expected a number in [1.4142135623730951, inf) (1 with connectivity 4 or corner cutting)");
}

TEST(GonumDStarLite, AFractionalDiagonalCostIsExact) {
  const GridMap map{"open", 3, 1, {false, false, false}};
  ReplanOptions o = replan_option_table().parse_flags({{"diagonal-cost", "1.5"}, {"known-map", "true"}});
  const GridMap square{"open", 3, 3, std::vector<bool>(9, false)};
  const ReplanResult r = drive_through_unknown_map(square, {0, 0}, {2, 2}, o);
  EXPECT_EQ(r.traversed.size(), 3u);  // two diagonals (3) beat four straight moves (4)
  EXPECT_EQ(r.grid.text(r.traversed_cost), "3");
  const ReplanResult line = drive_through_unknown_map(map, {0, 0}, {2, 0}, o);
  EXPECT_EQ(line.grid.text(line.traversed_cost), "2");
}

}  // namespace
}  // namespace polyplan
