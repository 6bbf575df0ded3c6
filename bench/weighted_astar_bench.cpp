// Weighted A* as the textbook's (a closed vertex is never reopened) against weighted A* that
// reopens closed vertices and against plain A*, on data/worlds/office.json's raster at 400 cells
// per side (docs/search_trace.md): the time of one query and its counts, every query of the world
// in turn. The raster is built once per search, outside the timing.
//
//   WeightedAStar/astar          A*
//   WeightedAStar/wastar_20      weighted A*, w = 20, no reopening (the default)
//   WeightedAStar/wastar_20_reopen   the same reopening closed vertices
// Counters: expanded and generated, summed over the world's queries.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/grids/raster_planner.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>

#include <benchmark/benchmark.h>

#include <cstdint>

namespace {

using namespace polyplan;

void WeightedAStar(benchmark::State& state, SearchOptions search) {
  const World world = read_world(POLYPLAN_DATA_DIR "/worlds/office.json");
  const CSpace cspace(world);
  RasterOptions options;
  options.resolution = 400;
  options.search = search;
  RasterPlanner planner(cspace, options);
  std::int64_t expanded = 0, generated = 0;
  for (auto _ : state) {
    expanded = generated = 0;
    for (const Query& q : world.queries) {
      const auto report = planner.plan(q);
      expanded += report.facts.at(SearchFacts::expanded);
      generated += report.facts.at(SearchFacts::generated);
    }
  }
  state.counters["expanded"] = static_cast<double>(expanded);
  state.counters["generated"] = static_cast<double>(generated);
}

SearchOptions weighted(bool reopen) {
  SearchOptions options{Search::wastar, 20.0};
  options.reopen = reopen;
  return options;
}

}  // namespace

BENCHMARK_CAPTURE(WeightedAStar, astar, SearchOptions{Search::astar})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(WeightedAStar, wastar_20, weighted(false))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(WeightedAStar, wastar_20_reopen, weighted(true))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
