// Visibility-graph construction: polyplan's triangular expansion against the naive exact
// construction (every pair of boundary vertices tested with check_path: O(n^2) pairs, each O(n)),
// on the same worlds of 250 to 2000 obstacle vertices, in the same run. The naive builder is the
// full graph's definition, so the peer is VisibilityKind::full; the reduced graph is timed too.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include "bench_worlds.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace polyplan;

using bench::quadrilaterals;

std::vector<ExactPoint> boundary_vertices(const CSpace& cspace) {
  std::vector<ExactPoint> nodes;
  for (const FreeComponent& c : cspace.free_components()) {
    nodes.insert(nodes.end(), c.outer.begin(), c.outer.end());
    for (const Ring& h : c.holes) nodes.insert(nodes.end(), h.begin(), h.end());
  }
  return nodes;
}

void TriangularExpansionFull(benchmark::State& state) {
  const CSpace cspace(quadrilaterals(static_cast<int>(state.range(0))));
  std::size_t edges = 0;
  for (auto _ : state) edges = boost::num_edges(VisibilityGraph(cspace, VisibilityKind::full).roadmap());
  state.counters["edges"] = static_cast<double>(edges);
}

void TriangularExpansionReduced(benchmark::State& state) {
  const CSpace cspace(quadrilaterals(static_cast<int>(state.range(0))));
  std::size_t edges = 0;
  for (auto _ : state) edges = boost::num_edges(VisibilityGraph(cspace, VisibilityKind::reduced).roadmap());
  state.counters["edges"] = static_cast<double>(edges);
}

void NaiveAllPairs(benchmark::State& state) {
  const CSpace cspace(quadrilaterals(static_cast<int>(state.range(0))));
  const auto nodes = boundary_vertices(cspace);
  std::size_t edges = 0;
  for (auto _ : state) {
    edges = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (std::size_t j = i + 1; j < nodes.size(); ++j) edges += check_path(cspace, {nodes[i], nodes[j]}).valid;
  }
  state.counters["edges"] = static_cast<double>(edges);
}

}  // namespace

BENCHMARK(TriangularExpansionFull)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(TriangularExpansionReduced)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(NaiveAllPairs)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
