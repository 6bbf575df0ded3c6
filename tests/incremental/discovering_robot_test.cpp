// The robot that discovers its map, judged as an outsider would: its knowledge rebuilt from the
// cells it traversed, and at every step the reported cost checked against a Dijkstra on that
// knowledge (written here) and the move taken checked to lie on a shortest path.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/io/movingai_map.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <ostream>
#include <queue>
#include <random>
#include <string>
#include <vector>

namespace polyplan {

inline void PrintTo(const OctileLength& l, std::ostream* out) { *out << l.to_string(); }

namespace {

GridMap map_of(const std::vector<std::string>& rows) {
  std::string text =
      "type octile\nheight " + std::to_string(rows.size()) + "\nwidth " + std::to_string(rows[0].size()) + "\nmap\n";
  for (const auto& row : rows) text += row + "\n";
  return parse_movingai_map(text, "test.map");
}

// What the robot believed blocked after sensing at traversed[0..i].
struct Belief {
  int width, height;
  std::vector<bool> blocked;
  bool at(int x, int y) const { return x < 0 || y < 0 || x >= width || y >= height || blocked[y * width + x]; }
  OctileLength cost(GridPoint a, GridPoint b) const {
    const int dx = b.x - a.x, dy = b.y - a.y;
    if (at(a.x, a.y) || at(b.x, b.y)) return OctileLength::infinity();
    if (dx != 0 && dy != 0 && (at(a.x + dx, a.y) || at(a.x, a.y + dy))) return OctileLength::infinity();
    return dx != 0 && dy != 0 ? OctileLength(0, 1) : OctileLength(1, 0);
  }
  // Distances to `goal` from every cell (costs are symmetric).
  std::vector<OctileLength> distances_to(GridPoint goal) const {
    std::vector<OctileLength> d(static_cast<std::size_t>(width) * height, OctileLength::infinity());
    using Item = std::pair<OctileLength, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    d[goal.y * width + goal.x] = {};
    open.push({{}, goal.y * width + goal.x});
    while (!open.empty()) {
      const auto [du, u] = open.top();
      open.pop();
      if (du != d[u]) continue;
      const GridPoint p{u % width, u / width};
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const GridPoint q{p.x + dx, p.y + dy};
          if ((dx == 0 && dy == 0) || at(q.x, q.y)) continue;
          const OctileLength through = du + cost(q, p);
          if (through < d[q.y * width + q.x]) {
            d[q.y * width + q.x] = through;
            open.push({through, q.y * width + q.x});
          }
        }
    }
    return d;
  }
};

void sense(const GridMap& truth, GridPoint at, double radius, Belief& belief) {
  for (int y = 0; y < truth.height; ++y)
    for (int x = 0; x < truth.width; ++x)
      if ((x - at.x) * (x - at.x) + (y - at.y) * (y - at.y) <= radius * radius)
        belief.blocked[y * truth.width + x] = truth.is_blocked(x, y);
}

// Every step's cost is the optimum on the knowledge of that moment; every move lies on a
// shortest path; the traversed cost adds up.
void check_every_step(const GridMap& truth, GridPoint goal, double radius, const ReplanResult& r) {
  Belief belief{truth.width, truth.height, std::vector<bool>(truth.blocked.size(), false)};
  OctileLength traversed;
  ASSERT_EQ(r.traversed.size(), r.moves + 1);
  ASSERT_EQ(r.steps.size(), r.found ? r.moves : r.moves + 1);
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const GridPoint at = r.traversed[i];
    ASSERT_EQ(r.steps[i].at, at);
    sense(truth, at, radius, belief);
    const auto d = belief.distances_to(goal);
    ASSERT_EQ(r.steps[i].cost_to_goal, d[at.y * truth.width + at.x]) << "step " << i;
    if (i + 1 < r.traversed.size()) {
      const GridPoint next = r.traversed[i + 1];
      const OctileLength move = belief.cost(at, next);
      ASSERT_EQ(move + d[next.y * truth.width + next.x], d[at.y * truth.width + at.x])
          << "move " << i << " is off every shortest path";
      ASSERT_FALSE(truth.is_blocked(next.x, next.y));
      traversed = traversed + move;
    }
  }
  EXPECT_EQ(r.traversed_cost, traversed);
  if (r.found) {
    EXPECT_EQ(r.traversed.back(), goal);
  } else {
    EXPECT_EQ(r.steps.back().cost_to_goal, OctileLength::infinity());
  }
}

constexpr ReplanAlgorithm all_algorithms[] = {ReplanAlgorithm::dstar_lite, ReplanAlgorithm::lpastar,
                                              ReplanAlgorithm::astar};

ReplanResult drive(const GridMap& map, GridPoint start, GridPoint goal, ReplanAlgorithm algorithm,
                   double radius = 1.5) {
  ReplanOptions options;
  options.algorithm = algorithm;
  options.sensor_radius = radius;
  return drive_through_unknown_map(map, start, goal, options);
}

GridMap random_map(int width, int height, double blocked, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::bernoulli_distribution wall(blocked);
  std::vector<std::string> rows(height, std::string(width, '.'));
  for (auto& row : rows)
    for (char& c : row) c = wall(random) ? '@' : '.';
  rows[0][0] = rows[height - 1][width - 1] = '.';
  return map_of(rows);
}

TEST(DiscoveringRobot, EveryStepIsOptimalOnWhatItKnowsOnRandomMaps) {
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const GridMap map = random_map(25, 18, 0.3, seed);
    for (const ReplanAlgorithm algorithm : all_algorithms)
      for (const double radius : {1.5, 3.0}) {
        SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::string(to_string(algorithm)) + ", R " +
                     std::to_string(radius));
        const ReplanResult r = drive(map, {0, 0}, {24, 17}, algorithm, radius);
        EXPECT_TRUE(r.status == PlanStatus::solved || r.status == PlanStatus::no_path);
        check_every_step(map, {24, 17}, radius, r);
      }
  }
}

TEST(DiscoveringRobot, TheThreeAlgorithmsPlanTheSameCostsAndDStarLiteDoesLessWork) {
  // A room whose wall the robot discovers only on arrival, many times over.
  std::vector<std::string> rows(30, std::string(40, '.'));
  for (int y = 0; y < 26; ++y) rows[y][20] = '@';
  for (int x = 5; x < 36; ++x) rows[15][x] = x == 30 ? '.' : '@';
  const GridMap map = map_of(rows);
  std::vector<ReplanResult> results;
  for (const ReplanAlgorithm algorithm : all_algorithms) results.push_back(drive(map, {2, 2}, {38, 3}, algorithm));
  for (const ReplanResult& r : results) {
    ASSERT_TRUE(r.found) << to_string(r.algorithm);
    check_every_step(map, {38, 3}, 1.5, r);
    EXPECT_EQ(r.traversed_cost, results[0].traversed_cost) << to_string(r.algorithm);
    EXPECT_EQ(r.replans, results[0].replans) << to_string(r.algorithm);
  }
  EXPECT_GT(results[0].replans, 10u);
  EXPECT_LT(3 * results[0].expanded, results[2].expanded)
      << "D* Lite " << results[0].expanded << ", A* " << results[2].expanded;
  EXPECT_LT(results[1].expanded, results[2].expanded)
      << "LPA* " << results[1].expanded << ", A* " << results[2].expanded;
}

TEST(DiscoveringRobot, AGoalInAClosedRoomEndsWithNoPathAfterTheRobotHasSeenTheRoom) {
  const GridMap map = map_of({
      "..........",
      "......@@@@",
      "......@..@",
      "......@..@",
      "......@@@@",
  });
  for (const ReplanAlgorithm algorithm : all_algorithms) {
    const ReplanResult r = drive(map, {0, 0}, {7, 2}, algorithm);
    EXPECT_EQ(r.status, PlanStatus::no_path) << to_string(algorithm);
    EXPECT_FALSE(r.found);
    EXPECT_GT(r.moves, 3u);  // it had to drive there to find out
    EXPECT_TRUE(r.last_plan.empty());
    check_every_step(map, {7, 2}, 1.5, r);
  }
}

TEST(DiscoveringRobot, StartAtTheGoalMakesNoMove) {
  const GridMap map = map_of({"...", "..."});
  const ReplanResult r = drive(map, {1, 1}, {1, 1}, ReplanAlgorithm::dstar_lite);
  EXPECT_TRUE(r.found);
  EXPECT_EQ(r.moves, 0u);
  EXPECT_TRUE(r.steps.empty());
  EXPECT_EQ(r.traversed, (std::vector<GridPoint>{GridPoint{1, 1}}));
}

// A limit that comes before the first plan stops the drive inside its sense or its search, not
// after them: status limit, by the time, not the move limit.
TEST(DiscoveringRobot, TheTimeLimitStopsTheDriveWithinItsSenseOrSearch) {
  const GridMap map = random_map(600, 600, 0.1, 5);
  ReplanOptions options;
  options.time_limit = 1e-9;
  options.sensor_radius = 1e4;  // the whole map: the sense reads every cell, and stops at row 8
  const ReplanResult sensing = drive_through_unknown_map(map, {0, 0}, {599, 599}, options);
  EXPECT_EQ(sensing.status, PlanStatus::limit);
  EXPECT_TRUE(sensing.timed_out);
  EXPECT_EQ(sensing.replans, 0u);
  // A sensor of one cell (three rows: not timed): the first search, across 600 cells of unknown
  // map, stops at its first look at the clock (256 passes).
  options.sensor_radius = 1.5;
  const ReplanResult searching = drive_through_unknown_map(map, {0, 0}, {599, 599}, options);
  EXPECT_EQ(searching.status, PlanStatus::limit);
  EXPECT_TRUE(searching.timed_out);
  EXPECT_EQ(searching.replans, 1u);
  EXPECT_LE(searching.expanded, 256u);
  EXPECT_EQ(searching.moves, 0u);
  options.time_limit = 0;  // none: the move limit stops it
  options.max_moves = 1;
  const ReplanResult by_moves = drive_through_unknown_map(map, {0, 0}, {599, 599}, options);
  EXPECT_EQ(by_moves.status, PlanStatus::limit);
  EXPECT_FALSE(by_moves.timed_out);
}

TEST(DiscoveringRobot, BadInputIsRefusedNamingWhatIsWrong) {
  const GridMap map = map_of({"..@", "..."});
  const auto message = [&](GridPoint start, GridPoint goal, double radius) {
    try {
      drive(map, start, goal, ReplanAlgorithm::dstar_lite, radius);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({2, 0}, {0, 0}, 1.5), "test.map: the start (2, 0) is a blocked cell");
  EXPECT_EQ(message({0, 0}, {3, 1}, 1.5), "test.map: the goal (3, 1) is outside the 3 x 2 map");
  EXPECT_NE(message({0, 0}, {1, 1}, 1.0).find("sensor radius: must be a finite number of at least √2"),
            std::string::npos);
}

TEST(DiscoveringRobot, AnObstacleThatAppearsOnItsWayIsDrivenRound) {
  const GridMap map = map_of({
      "..........",
      "..........",
      "..........",
  });
  ReplanOptions options;
  // After three moves a wall rises across the middle row ahead of it, but for one gap.
  options.world_changes = [](std::size_t moves, GridMap& truth) {
    if (moves != 3) return false;
    for (int y = 0; y < 3; ++y) truth.blocked[y * truth.width + 6] = y != 2;
    return true;
  };
  const ReplanResult r = drive_through_unknown_map(map, {0, 1}, {9, 1}, options);
  ASSERT_TRUE(r.found);
  for (const GridPoint& p : r.traversed) EXPECT_FALSE(p.x == 6 && p.y != 2) << p.x << ", " << p.y;
  EXPECT_GT(r.traversed_cost, OctileLength(9, 0));
  EXPECT_EQ(r.truth.is_blocked(6, 0), true);
}

// The trace: passes numbered within each replan, and every open-list entry labelled as the course's planning problem
// set labels it.
struct Recorder : ReplanTrace {
  std::size_t replans = 0, passes = 0, wrong = 0;
  void replan_begins(std::size_t replan, GridPoint, std::size_t) override { wrong += replan != ++replans; }
  void pass(const ReplanTracePass& p) override {
    ++passes;
    wrong += p.replan != replans;
    for (const auto& e : p.open) wrong += e.state != (e.g > e.rhs ? "over" : "under") || e.g == e.rhs;
    for (const auto& u : p.updated)
      wrong += !(u.action == "add" || u.action == "readd" || u.action == "remove" || u.action.empty());
  }
};

TEST(DiscoveringRobot, TheTraceFollowsEveryReplan) {
  const GridMap map = random_map(12, 10, 0.25, 3);
  Recorder recorder;
  ReplanOptions options;
  options.trace = &recorder;
  const ReplanResult r = drive_through_unknown_map(map, {0, 0}, {11, 9}, options);
  EXPECT_EQ(recorder.replans, r.replans);
  EXPECT_GE(recorder.passes, r.expanded);
  EXPECT_EQ(recorder.wrong, 0u);
}

}  // namespace
}  // namespace polyplan
