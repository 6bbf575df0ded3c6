// Visibility-graph construction: polyplan's triangular expansion against the naive exact
// construction (every pair of boundary vertices tested with check_path: O(n^2) pairs, each O(n)),
// on the same worlds of 250 to 2000 obstacle vertices, in the same run. The naive builder is the
// full graph's definition, so the peer is VisibilityKind::full; the reduced graph is timed too.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace polyplan;

// n/4 random convex quadrilaterals on a jittered grid (they never overlap), in a box.
World quadrilaterals(int vertices) {
  const int count = vertices / 4, side = static_cast<int>(std::ceil(std::sqrt(count)));
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> jitter(0, 300);  // thousandths of a cell
  World world;
  world.source = "bench";
  world.bounds = Bounds{0, 0, side, side};
  for (int i = 0; i < count; ++i) {
    const int cx = i % side, cy = i / side;
    auto at = [&](int dx, int dy) {
      return ExactPoint{Rational(cx * 1000 + dx + jitter(rng), 1000), Rational(cy * 1000 + dy + jitter(rng), 1000)};
    };
    world.obstacles.push_back({{at(100, 100), at(550, 100), at(550, 550), at(100, 550)}, {}});
    world.obstacle_names.push_back("quad");
  }
  return world;
}

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
