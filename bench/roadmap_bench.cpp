// Build time and memory of the classical roadmaps against the visibility graph, in one run: every
// registered planner of polygon worlds among visibility, trapezoid, voronoi and gvd-grid, built
// on random worlds of 1,000 to 10,000 obstacle vertices (the growth shows whether a build is
// O(n log n)) and on three MovingAI maps traced into polygon worlds. Memory is the peak of the
// bytes the build allocates on the heap (operator new and GMP, counted), not the
// process's resident size, which the allocator's caching blurs (bench/heap_counter.hpp).
//
//   build/bench/roadmap_bench --benchmark_counters_tabular=true
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include "bench_worlds.hpp"
#include "heap_counter.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace polyplan;

const char* const kRoadmaps[] = {"visibility", "trapezoid", "voronoi", "gvd-grid"};

// Builds the planner `name` on the C-space once per iteration; counters: the peak heap bytes of
// one build above what the C-space holds, and the roadmap's size from a first query's facts.
void Build(benchmark::State& state, const std::string& name, const CSpace* cspace, int obstacle_vertices) {
  const PlannerEntry<TranslatingRobot>* entry = planners<TranslatingRobot>().find(name);
  long long peak_bytes = 0;
  for (auto _ : state) {
    std::unique_ptr<Planner<TranslatingRobot>> planner;
    peak_bytes = bench::peak_heap_bytes([&] { planner = entry->make(*cspace, {}); });
    benchmark::DoNotOptimize(planner.get());
  }
  const auto& world = cspace->world();
  if (!world.queries.empty()) {
    auto planner = entry->make(*cspace, {});
    const auto report = planner->plan(world.queries.front());
    state.counters["nodes"] = static_cast<double>(report.facts.at(RoadmapFacts::vertices));
    state.counters["edges"] = static_cast<double>(report.facts.at(RoadmapFacts::edges));
  }
  state.counters["n"] = obstacle_vertices;
  state.counters["heap_MB"] = static_cast<double>(peak_bytes) / 1e6;
}

int obstacle_vertex_count(const World& world) {
  std::size_t n = 0;
  for (const PolygonWithHoles& p : world.obstacles) {
    n += p.outer.size();
    for (const Ring& h : p.holes) n += h.size();
  }
  return static_cast<int>(n);
}

// The worlds live as long as the program: benchmarks run after main registered them.
const CSpace* keep(World world) {
  if (world.queries.empty()) {  // corner to corner, for the size facts
    const Bounds& b = *world.bounds;
    world.queries.push_back({{b.xmin + Rational(1, 100), b.ymin + Rational(1, 100)},
                             {b.xmax - Rational(1, 100), b.ymax - Rational(1, 100)},
                             "corners"});
  }
  return new CSpace(world);
}

}  // namespace

int main(int argc, char** argv) {
  bench::count_gmp_allocations();
  benchmark::Initialize(&argc, argv);
  for (int vertices : {1000, 2000, 4000, 10000}) {
    const World world = bench::quadrilaterals(vertices);
    const CSpace* cspace = keep(world);
    for (const char* name : kRoadmaps)
      if (planners<TranslatingRobot>().find(name))
        benchmark::RegisterBenchmark((std::string(name) + "/random/" + std::to_string(vertices)).c_str(), Build, name,
                                     cspace, vertices)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1);
  }
  for (const char* map : {"lak303d", "brc202d", "orz103d"}) {
    const World world =
        world_from_grid(read_movingai_map(std::string(POLYPLAN_BENCHMARK_DIR) + "/maps/" + map + ".map"));
    const CSpace* cspace = keep(world);
    for (const char* name : kRoadmaps)
      if (planners<TranslatingRobot>().find(name))
        benchmark::RegisterBenchmark((std::string(name) + "/" + map).c_str(), Build, name, cspace,
                                     obstacle_vertex_count(world))
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
