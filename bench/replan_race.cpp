// D* Lite and LPA* against repeated A* (docs/replan_race.md), in the same run, on the same graph,
// costs and heap: only what each search reuses differs.
//
//   robot  on MovingAI maps (data/movingai/ and ../shared/benchmarks/movingai/): a robot that
//          discovers the map drives each of --queries start/goal pairs of the map's scenario file
//          (spread evenly over the file, so over its buckets), at each sensor radius; the totals of
//          expansions, heap operations and replanning time per algorithm.
//   maze   Koenig & Likhachev's LPA* setting: a 61 x 61 grid with 30 % of its cells blocked at
//          random, start and goal fixed in opposite corners, --toggle of the cells (0.1 %) toggled
//          between replanning episodes, --episodes episodes; LPA* and D* Lite against A* from scratch.
//
//   replan_race [--maps DIR ...] [--queries 100] [--radii 1.5,5,20] [--episodes 500] [--seed 1]
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/search/changing_grid.hpp>
#include <polyplan/search/incremental_search.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace polyplan;

constexpr ReplanAlgorithm algorithms[] = {ReplanAlgorithm::dstar_lite, ReplanAlgorithm::lpastar,
                                          ReplanAlgorithm::astar};

struct Totals {
  std::size_t expanded = 0, heap_operations = 0, replans = 0, moves = 0, solved = 0;
  double seconds = 0;
};

void print_row(const std::string& name, double radius, const Totals (&t)[3]) {
  const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  std::printf("%-22s %5.1f %8zu %8zu | %12zu %12zu %12zu | %9.3f %9.3f %9.3f | %6.3f %6.3f | %6.3f %6.3f\n",
              name.c_str(), radius, t[2].replans, t[2].solved, t[0].expanded, t[1].expanded, t[2].expanded,
              t[0].seconds, t[1].seconds, t[2].seconds, ratio(t[0].expanded, t[2].expanded),
              ratio(t[1].expanded, t[2].expanded), ratio(t[0].seconds, t[2].seconds),
              ratio(t[1].seconds, t[2].seconds));
  std::fflush(stdout);
}

void header(const char* first) {
  std::printf("%-22s %5s %8s %8s | %12s %12s %12s | %9s %9s %9s | %13s | %13s\n", first, "R", "replans", "solved",
              "exp D*Lite", "exp LPA*", "exp A*", "s D*Lite", "s LPA*", "s A*", "exp / A*", "time / A*");
}

void race_map(const std::filesystem::path& map_file, const std::filesystem::path& scenario_file, std::size_t queries,
              const std::vector<double>& radii) {
  const GridMap map = read_movingai_map(map_file.string());
  const std::vector<ScenarioQuery> all = read_scenarios(scenario_file.string());
  std::vector<ScenarioQuery> chosen;
  for (std::size_t i = 0; i < queries && i < all.size(); ++i)
    chosen.push_back(all[i * all.size() / std::min(queries, all.size())]);
  for (const double radius : radii) {
    Totals t[3];
    for (const ScenarioQuery& q : chosen)
      for (int a = 0; a < 3; ++a) {
        ReplanOptions options;
        options.algorithm = algorithms[a];
        options.sensor_radius = radius;
        const ReplanResult r = drive_through_unknown_map(map, {q.start_x, q.start_y}, {q.goal_x, q.goal_y}, options);
        t[a].expanded += r.expanded;
        t[a].heap_operations += r.heap_operations;
        t[a].replans += r.replans;
        t[a].moves += r.moves;
        t[a].solved += r.found;
        t[a].seconds += r.seconds;
      }
    print_row(map_file.filename().string(), radius, t);
  }
}

// The LPA* experiment: fixed start and goal, cells toggled between episodes.
// The maze: 30 % of the cells blocked at random, the corners free.
ChangingGrid maze(std::uint32_t seed) {
  std::mt19937 random(seed);
  std::bernoulli_distribution blocked(0.3);
  ChangingGrid grid(61, 61);
  std::vector<ChangedMove> ignored;
  for (GridCell c = 1; c + 1 < grid.graph().cell_count(); ++c)
    if (blocked(random)) grid.set_blocked(c, true, ignored);
  return grid;
}

template <class Search>
double episodes(std::size_t count, std::size_t toggles, std::uint32_t seed, bool from_scratch, std::size_t& expanded,
                std::size_t& solved) {
  ChangingGrid grid = maze(seed);
  const GridCell start = grid.cell(0, 0), goal = grid.cell(grid.width() - 1, grid.height() - 1);
  Search search(grid.graph(), {&grid}, {&grid}, start, goal);
  std::mt19937 random(seed + 1);
  std::uniform_int_distribution<GridCell> any(0, grid.graph().cell_count() - 1);
  std::vector<ChangedMove> changed;
  double seconds = 0;
  for (std::size_t e = 0; e < count; ++e) {
    changed.clear();
    for (std::size_t k = 0; k < toggles; ++k) {
      const GridCell c = any(random);
      if (c != start && c != goal) grid.set_blocked(c, !grid.blocked(c), changed);
    }
    const auto began = std::chrono::steady_clock::now();
    if (from_scratch) {
      search.restart();
    } else {
      for (const ChangedMove& m : changed) search.edge_changed(m.from, m.to, m.old_cost);
    }
    solved += search.compute_shortest_path();
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  }
  expanded = search.counts().expanded;
  return seconds;
}

void race_maze(std::size_t count, std::uint32_t seed) {
  const std::size_t toggles = 4;  // 0.1 % of 3,721 cells
  using Lpa = LpaStar<GridGraph, ChangingGridCosts, ChangingGridDistance>;
  using DLite = DStarLite<GridGraph, ChangingGridCosts, ChangingGridDistance>;
  Totals t[3];
  t[0].seconds = episodes<DLite>(count, toggles, seed, false, t[0].expanded, t[0].solved);
  t[1].seconds = episodes<Lpa>(count, toggles, seed, false, t[1].expanded, t[1].solved);
  t[2].seconds = episodes<DLite>(count, toggles, seed, true, t[2].expanded, t[2].solved);
  t[2].replans = count;
  print_row("maze 61x61 30%, 4 cells", 0, t);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("D* Lite and LPA* against repeated A*");
  std::vector<std::string> dirs{POLYPLAN_DATA_DIR "/movingai", POLYPLAN_BENCHMARK_DIR};
  std::size_t queries = 100, count = 500;
  std::vector<double> radii{1.5, 5, 20};
  std::uint32_t seed = 1;
  app.add_option("--maps", dirs, "Folders with maps/ and scenarios/")->capture_default_str();
  app.add_option("--queries", queries, "Queries per map, spread over its scenario file")->capture_default_str();
  app.add_option("--radii", radii, "Sensor radii")->delimiter(',')->capture_default_str();
  app.add_option("--episodes", count, "Replanning episodes of the maze")->capture_default_str();
  app.add_option("--seed", seed, "The maze's seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  header("maze");
  race_maze(count, seed);
  header("map");
  for (const std::filesystem::path dir : dirs) {
    if (!std::filesystem::exists(dir / "maps")) continue;
    std::vector<std::filesystem::path> maps;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "maps")) maps.push_back(entry.path());
    std::sort(maps.begin(), maps.end());
    for (const auto& map : maps) race_map(map, dir / "scenarios" / (map.filename().string() + ".scen"), queries, radii);
  }
}
