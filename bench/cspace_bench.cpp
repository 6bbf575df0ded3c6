// Why CSpace joins all obstacles in one aggregated union: joining them one at a time re-sweeps
// the growing arrangement at every step (quadratic). Both on the same staggered field of
// overlapping squares, in the same run.
#include <polyplan/geometry/cspace.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <benchmark/benchmark.h>

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;

// n squares of side 3 on a staggered grid of pitch 2: neighbours overlap.
std::vector<Polygon> squares(int n) {
  std::vector<Polygon> result;
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    const int x = (i % side) * 4 + (i / side) % 2, y = (i / side) * 4;
    Polygon p;
    p.push_back({x, y});
    p.push_back({x + 3, y});
    p.push_back({x + 3, y + 3});
    p.push_back({x, y + 3});
    result.push_back(p);
  }
  return result;
}

void AggregatedJoin(benchmark::State& state) {
  const auto polygons = squares(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    CGAL::Polygon_set_2<Kernel> set;
    set.join(polygons.begin(), polygons.end());
    benchmark::DoNotOptimize(set.number_of_polygons_with_holes());
  }
}

void OneAtATimeJoin(benchmark::State& state) {
  const auto polygons = squares(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    CGAL::Polygon_set_2<Kernel> set;
    for (const auto& p : polygons) set.join(p);
    benchmark::DoNotOptimize(set.number_of_polygons_with_holes());
  }
}

// The whole C-space of a robot among those squares, through the public interface.
void BuildCSpace(benchmark::State& state) {
  polyplan::World world;
  world.source = "bench";
  for (const auto& p : squares(static_cast<int>(state.range(0)))) {
    polyplan::Ring ring;
    for (const auto& v : p.vertices())
      ring.push_back({polyplan::Rational(CGAL::to_double(v.x())), polyplan::Rational(CGAL::to_double(v.y()))});
    world.obstacles.push_back({ring, {}});
    world.obstacle_names.push_back("square");
  }
  world.robot.parts.push_back({{0, 0}, {1, 0}, {0, 1}});
  for (auto _ : state) {
    polyplan::CSpace cspace(world);
    benchmark::DoNotOptimize(cspace.free_components().size());
  }
}

}  // namespace

BENCHMARK(AggregatedJoin)->RangeMultiplier(4)->Range(64, 4096)->Unit(benchmark::kMillisecond);
BENCHMARK(OneAtATimeJoin)->RangeMultiplier(4)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BuildCSpace)->RangeMultiplier(4)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
