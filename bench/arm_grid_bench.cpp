// Lazy against eager evaluation of the two-link arm's C-space grid (the course's graph-search homework optional 3.2):
// the same A* on the same grid, the cells decided when the search reaches them or all up front. Both in one run, for
// each query of data/arms/two_link_points.json at 5 and 1 degrees; the counters are the cells evaluated (collision
// checks of grid configurations) and the moves checked.
#include <polyplan/arm/arm_facts.hpp>
#include <polyplan/arm/arm_grid_planner.hpp>
#include <polyplan/io/arm_reader.hpp>

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace polyplan;

const ArmProblem& two_link() {
  static const ArmProblem p = read_arm_problem(std::string(POLYPLAN_DATA_DIR) + "/arms/two_link_points.json");
  return p;
}

void plan(benchmark::State& state, bool lazy) {
  const ArmProblem& p = two_link();
  const ArmQuery& q = p.queries.at(static_cast<std::size_t>(state.range(0)));
  ArmGridOptions options;
  options.lazy = lazy;
  options.resolution_degrees = static_cast<double>(state.range(1));
  ArmGridPlanner planner(p, options);
  PlanReport<JointAngles> last;
  for (auto _ : state) {
    last = planner.plan(q);
    benchmark::DoNotOptimize(last.path.data());
  }
  state.SetLabel(q.name + (last.found ? "" : " (no path)"));
  for (const FactKey<std::int64_t> count :
       {ArmGridFacts::cells_evaluated, ArmGridFacts::moves_checked, ArmGridFacts::expanded})
    state.counters[std::string(count.name)] = static_cast<double>(last.facts.at(count));
  state.counters["length"] = last.length;
}

void BM_TwoLinkLazy(benchmark::State& state) { plan(state, true); }
void BM_TwoLinkEager(benchmark::State& state) { plan(state, false); }

// Queries 0, 1, 2 (easy, medium, hard) at 5 and 1 degrees.
void queries(benchmark::internal::Benchmark* b) {
  for (int resolution : {5, 1})
    for (int query = 0; query < 3; ++query) b->Args({query, resolution});
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_TwoLinkLazy)->Apply(queries);
BENCHMARK(BM_TwoLinkEager)->Apply(queries);

}  // namespace

BENCHMARK_MAIN();
