// What exact length comparisons cost (geometry/root_sum.hpp, geometry/chain_lengths.hpp): a
// visibility-graph query's A* in doubles alone, against the same A* followed by the exact pass
// that proves its path shortest (search/exact_shortest_path.hpp), on the roadmap benchmarks'
// random worlds of 250 to 2000 obstacle vertices, the same corner pairs in the same run; and one
// exact comparison where bounds decide it and where only CORE can (a tie).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/root_sum.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/search/exact_shortest_path.hpp>
#include <polyplan/search/shortest_path.hpp>
#include "bench_worlds.hpp"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace polyplan;

struct Queries {
  CSpace cspace;
  VisibilityGraph graph;
  std::vector<std::pair<RoadmapVertexId, RoadmapVertexId>> pairs;
  explicit Queries(int vertices) : cspace(bench::quadrilaterals(vertices)), graph(cspace, VisibilityKind::reduced) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<std::size_t> corner(0, graph.corner_count() - 1);
    for (int i = 0; i < 50; ++i) pairs.emplace_back(corner(rng), corner(rng));
  }
};

void run(benchmark::State& state, bool exact) {
  const Queries q(static_cast<int>(state.range(0)));
  SearchWorkspace<RoadmapVertexId> workspace;
  std::size_t changed = 0;
  for (auto _ : state)
    for (const auto& [a, b] : q.pairs) {
      const auto result = shortest_path(q.graph.roadmap(), a, b, {Search::astar}, workspace);
      if (exact && result.found) changed += exactly_shortest_path(q.graph.roadmap(), result.path) != result.path;
      benchmark::DoNotOptimize(result.path.data());
    }
  state.counters["queries"] = static_cast<double>(q.pairs.size());
  state.counters["paths_changed"] = static_cast<double>(changed);
}

void AStarInDoubles(benchmark::State& state) { run(state, false); }
void AStarThenExactPass(benchmark::State& state) { run(state, true); }

RootSum tether(const char* x, const char* y) {
  return RootSum::polyline({{0, 0}, {*parse_rational(x), *parse_rational(y)}, {2 * *parse_rational(x), 0}});
}

void CompareDecidedByBounds(benchmark::State& state) {
  const RootSum a = tether("0.51", "0.68"), b = tether("0.51", "0.69");
  for (auto _ : state) benchmark::DoNotOptimize(compare(a, b));
}

void CompareTieDecidedByCore(benchmark::State& state) {
  const RootSum a = tether("0.51", "0.68");
  const Rational L(17, 10);
  for (auto _ : state) benchmark::DoNotOptimize(compare(a, L));
}

}  // namespace

BENCHMARK(AStarInDoubles)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK(AStarThenExactPass)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK(CompareDecidedByBounds);
BENCHMARK(CompareTieDecidedByCore)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
