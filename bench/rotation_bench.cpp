// The rotation planner's cost against the number of orientations (36, 72, 180, 360 layers) on the
// two shipped rotation worlds: building every layer's and turn layer's exact C-space and the
// roadmap over them (time, peak heap including GMP's exact numbers), and answering a query once
// built. The peer in the same run is the translating visibility graph of one layer (C-space and
// graph), the work a layer would cost were it built alone.
//
//   build/bench/rotation_bench --benchmark_counters_tabular=true
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/rotation/rotation_planner.hpp>
#include "heap_counter.hpp"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace {

using namespace polyplan;

RotationOptions layers(std::size_t count) {
  RotationOptions options;
  options.orientations.count = count;
  return options;
}

void Build(benchmark::State& state, const World* world) {
  const auto count = static_cast<std::size_t>(state.range(0));
  long long peak_bytes = 0;
  std::unique_ptr<RotationPlanner> planner;
  for (auto _ : state) {
    planner.reset();
    peak_bytes = bench::peak_heap_bytes([&] { planner = std::make_unique<RotationPlanner>(*world, layers(count)); });
  }
  const auto report = planner->plan(world->queries.front());
  state.counters["layers"] = static_cast<double>(count);
  state.counters["heap_MB"] = static_cast<double>(peak_bytes) / 1e6;
  state.counters["vertices"] = static_cast<double>(report.facts.at(RoadmapFacts::vertices));
  state.counters["edges"] = static_cast<double>(report.facts.at(RoadmapFacts::edges));
  state.counters["found"] = report.found;
}

void Answer(benchmark::State& state, const World* world) {
  RotationPlanner planner(*world, layers(static_cast<std::size_t>(state.range(0))));
  PlanReport<Pose> report;
  for (auto _ : state) report = planner.plan(world->queries.front());
  state.counters["layers"] = static_cast<double>(state.range(0));
  state.counters["expanded"] = static_cast<double>(report.facts.at(SearchFacts::expanded));
  state.counters["found"] = report.found;
}

// The peer: one layer's C-space and visibility graph, built alone.
void OneTranslatingLayer(benchmark::State& state, const World* world) {
  long long peak_bytes = 0;
  for (auto _ : state) {
    peak_bytes = bench::peak_heap_bytes([&] {
      const CSpace cspace(*world);
      VisibilityGraph graph(cspace);
      benchmark::DoNotOptimize(&graph);
    });
  }
  state.counters["layers"] = 1;
  state.counters["heap_MB"] = static_cast<double>(peak_bytes) / 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  bench::count_gmp_allocations();
  benchmark::Initialize(&argc, argv);
  for (const char* name : {"rotation_seed004", "rotation_piano"}) {
    const World* world = new World(read_world(std::string(POLYPLAN_DATA_DIR) + "/worlds/" + name + ".json"));
    benchmark::RegisterBenchmark((std::string("visibility_one_layer/") + name).c_str(), OneTranslatingLayer, world)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("rotation_build/") + name).c_str(), Build, world)
        ->Arg(36)
        ->Arg(72)
        ->Arg(180)
        ->Arg(360)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark((std::string("rotation_query/") + name).c_str(), Answer, world)
        ->Arg(36)
        ->Arg(72)
        ->Arg(180)
        ->Arg(360)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
