// Query time of the visibility graph on the MovingAI maps (every scenario query, one roadmap per
// map). Polyanya's means measured on this kind of machine are in the benchmark data's README
// (arena 0.9 us, den312d 3.8 us, lak303d 73 us, brc202d 152 us, orz103d 165 us); the counters
// report ours next to them.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace polyplan;

void Queries(benchmark::State& state, const std::string& name, double polyanya_us) {
  const std::string dir = POLYPLAN_BENCHMARK_DIR;
  const CSpace cspace(world_from_grid(read_movingai_map(dir + "/maps/" + name + ".map")));
  VisibilityGraph graph(cspace);
  const auto queries = read_scenarios(dir + "/scenarios/" + name + ".map.scen");
  std::size_t answered = 0;
  for (auto _ : state)
    for (const ScenarioQuery& q : queries) {
      benchmark::DoNotOptimize(graph.plan(Query{{q.start_x, q.start_y}, {q.goal_x, q.goal_y}, "q"}).length);
      ++answered;
    }
  state.counters["us_per_query"] =
      benchmark::Counter(static_cast<double>(answered), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["us_per_query"] = state.counters["us_per_query"] * 1e6;
  state.counters["polyanya_us"] = polyanya_us;
  state.counters["roadmap_edges"] = static_cast<double>(boost::num_edges(graph.roadmap()));
}

}  // namespace

BENCHMARK_CAPTURE(Queries, arena, std::string("arena"), 0.9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(Queries, den312d, std::string("den312d"), 3.8)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(Queries, lak303d, std::string("lak303d"), 73)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(Queries, brc202d, std::string("brc202d"), 152)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(Queries, orz103d, std::string("orz103d"), 165)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
