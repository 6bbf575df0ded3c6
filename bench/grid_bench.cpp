// Expansions per second of the library's grid A* (BGL astar_search_no_init through shortest_path on
// the implicit GridGraph, one reused workspace: grids/movingai_grid.hpp) against the peer a
// person would write by hand for MovingAI maps: a flat-array A* with an octile heuristic, a binary
// heap with lazy deletion and per-query generation stamps instead of clearing. Same maps, same
// queries (a few hundred per map, every bucket), same run. The goal: BGL >= 0.8x the peer's rate.
//
//   GridAStar/bgl/MAP, GridAStar/flat/MAP  each engine alone: counter expansions_per_second
//   GridAStar/ratio/MAP                    both engines on every iteration, interleaved (so that
//                                          load from other processes hits both alike): ratio =
//                                          bgl rate / flat rate, and each rate
// Both engines must find the same lengths, or the benchmark stops with an error.
#include <polyplan/grids/movingai_grid.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>

#include <benchmark/benchmark.h>

#include <time.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace polyplan;

// ---- the peer: a minimal, well-made flat-array A* for 8-connected grids without corner cutting ----

class FlatOctileAStar {
 public:
  struct Answer {
    bool found = false;
    double cost = 0;
    std::size_t expanded = 0, path_cells = 0;
  };

  // A border of blocked cells around the map: no bounds checks on the hot path.
  explicit FlatOctileAStar(const GridMap& map)
      : width_(map.width + 2), free_(static_cast<std::size_t>(width_) * (map.height + 2), 0), nodes_(free_.size()) {
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < map.width; ++x) free_[index(x, y)] = !map.is_blocked(x, y);
    const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    for (int d = 0; d < 8; ++d) moves_[d] = {dx[d], dy[d], dy[d] * width_ + dx[d], d < 4 ? 1.0 : std::sqrt(2.0)};
  }

  Answer search(int sx, int sy, int gx, int gy) {
    if (++generation_ == 0) {  // after 2^32 - 1 queries: make every stamp stale once
      for (Node& n : nodes_) n.seen = n.closed = 0;
      generation_ = 1;
    }
    const auto start = static_cast<std::uint32_t>(index(sx, sy)), goal = static_cast<std::uint32_t>(index(gx, gy));
    const int goal_x = gx + 1, goal_y = gy + 1;
    const double sqrt2_minus_1 = sqrt2_minus_1_;
    const auto h = [=](int x, int y) {
      const double a = std::abs(x - goal_x), b = std::abs(y - goal_y);
      return a < b ? b + sqrt2_minus_1 * a : a + sqrt2_minus_1 * b;
    };
    open_.clear();
    nodes_[start] = {0.0, start, generation_, 0};
    push({h(sx + 1, sy + 1), 0.0, start});
    Answer answer;
    while (!open_.empty()) {
      const Entry top = open_.front();
      std::pop_heap(open_.begin(), open_.end(), Worse{});
      open_.pop_back();
      Node& u = nodes_[top.cell];
      if (u.closed == generation_) continue;  // a stale entry: the cell was expanded with a lower g
      u.closed = generation_;
      ++answer.expanded;
      if (top.cell == goal) {
        answer.found = true;
        answer.cost = u.g;
        for (std::uint32_t c = goal; c != start; c = nodes_[c].parent) ++answer.path_cells;
        ++answer.path_cells;
        return answer;
      }
      const int ux = static_cast<int>(top.cell % width_), uy = static_cast<int>(top.cell / width_);
      for (const Move& m : moves_) {
        const std::uint32_t v = top.cell + m.offset;
        if (!free_[v]) continue;
        if (m.dx && m.dy && !(free_[top.cell + m.dx] && free_[top.cell + m.dy * width_])) continue;  // corner
        Node& n = nodes_[v];
        if (n.closed == generation_) continue;
        const double g = u.g + m.cost;
        if (n.seen == generation_ && g >= n.g) continue;
        n = {g, top.cell, generation_, n.closed};
        push({g + h(ux + m.dx, uy + m.dy), g, v});
      }
    }
    return answer;
  }

 private:
  struct Move {
    int dx, dy, offset;
    double cost;
  };
  struct Node {
    double g;
    std::uint32_t parent, seen, closed;
  };
  struct Entry {
    double f, g;
    std::uint32_t cell;
  };
  // The heap's order: lowest f first, ties to the larger g (deeper, nearer the goal). A type, not a
  // function pointer, so that the heap operations inline it.
  struct Worse {
    bool operator()(const Entry& a, const Entry& b) const { return a.f > b.f || (a.f == b.f && a.g < b.g); }
  };
  void push(const Entry& e) {
    open_.push_back(e);
    std::push_heap(open_.begin(), open_.end(), Worse{});
  }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y + 1) * width_ + (x + 1); }

  int width_;
  std::vector<std::uint8_t> free_;
  std::vector<Node> nodes_;
  Move moves_[8];
  std::vector<Entry> open_;  // kept between queries: its capacity is reused
  std::uint32_t generation_ = 0;
  const double sqrt2_minus_1_ = std::sqrt(2.0) - 1.0;  // computed once: the heuristic must not call sqrt
};

// ---- the problem set ----

struct Problem {
  GridMap map;
  std::vector<ScenarioQuery> queries;  // about 300, spread over every bucket of the file
};

const Problem& problem(const std::string& name) {
  static std::vector<std::pair<std::string, Problem>> loaded;
  for (const auto& [n, p] : loaded)
    if (n == name) return p;
  const std::string dir = POLYPLAN_BENCHMARK_DIR;
  Problem p{read_movingai_map(dir + "/maps/" + name + ".map"), {}};
  const auto all = read_scenarios(dir + "/scenarios/" + name + ".map.scen");
  const std::size_t stride = std::max<std::size_t>(1, all.size() / 300);
  for (std::size_t i = 0; i < all.size(); i += stride) p.queries.push_back(all[i]);
  check_scenarios_fit(p.map, p.queries, name);
  loaded.emplace_back(name, std::move(p));
  return loaded.back().second;
}

struct Totals {
  std::size_t expanded = 0;
  double seconds = 0, cost = 0;
};

// This thread's CPU time: on a machine shared with other work, preemption does not count against
// either engine (Google Benchmark's own rates use CPU time too).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Totals run_bgl(MovingAiGridSearch& grid, const std::vector<ScenarioQuery>& queries) {
  Totals t;
  const double began = thread_seconds();
  for (const ScenarioQuery& q : queries) {
    const auto r = grid.search(q);
    t.expanded += r.expanded;
    t.cost += r.cost;
  }
  t.seconds = thread_seconds() - began;
  return t;
}

Totals run_flat(FlatOctileAStar& flat, const std::vector<ScenarioQuery>& queries) {
  Totals t;
  const double began = thread_seconds();
  for (const ScenarioQuery& q : queries) {
    const auto r = flat.search(q.start_x, q.start_y, q.goal_x, q.goal_y);
    t.expanded += r.expanded;
    t.cost += r.cost;
  }
  t.seconds = thread_seconds() - began;
  return t;
}

void report(benchmark::State& state, const Problem& p, std::size_t expanded, std::size_t rounds) {
  state.counters["expansions_per_second"] =
      benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
  state.counters["expanded_per_query"] = static_cast<double>(expanded) / static_cast<double>(rounds * p.queries.size());
  state.counters["queries"] = static_cast<double>(p.queries.size());
}

void Bgl(benchmark::State& state, const std::string& name) {
  const Problem& p = problem(name);
  MovingAiGridSearch grid(p.map);
  std::size_t expanded = 0, rounds = 0;
  for (auto _ : state) {
    expanded += run_bgl(grid, p.queries).expanded;
    ++rounds;
  }
  report(state, p, expanded, rounds);
}

void Flat(benchmark::State& state, const std::string& name) {
  const Problem& p = problem(name);
  FlatOctileAStar flat(p.map);
  std::size_t expanded = 0, rounds = 0;
  for (auto _ : state) {
    expanded += run_flat(flat, p.queries).expanded;
    ++rounds;
  }
  report(state, p, expanded, rounds);
}

void Ratio(benchmark::State& state, const std::string& name) {
  const Problem& p = problem(name);
  MovingAiGridSearch grid(p.map);
  FlatOctileAStar flat(p.map);
  // Same answers first: a peer that finds other lengths would not be a peer.
  for (const ScenarioQuery& q : p.queries) {
    const auto a = grid.search(q);
    const auto b = flat.search(q.start_x, q.start_y, q.goal_x, q.goal_y);
    if (a.found != b.found || std::abs(a.cost - b.cost) > 1e-9) {
      state.SkipWithError(("the engines disagree on a query of " + name).c_str());
      return;
    }
  }
  Totals bgl, peer;
  for (auto _ : state) {
    const Totals a = run_bgl(grid, p.queries), b = run_flat(flat, p.queries);
    bgl.expanded += a.expanded, bgl.seconds += a.seconds;
    peer.expanded += b.expanded, peer.seconds += b.seconds;
  }
  const double bgl_rate = static_cast<double>(bgl.expanded) / bgl.seconds;
  const double flat_rate = static_cast<double>(peer.expanded) / peer.seconds;
  state.counters["bgl_expansions_per_second"] = bgl_rate;
  state.counters["flat_expansions_per_second"] = flat_rate;
  state.counters["ratio"] = bgl_rate / flat_rate;
  state.counters["bgl_expanded_per_query"] =
      static_cast<double>(bgl.expanded) / static_cast<double>(state.iterations() * p.queries.size());
  state.counters["flat_expanded_per_query"] =
      static_cast<double>(peer.expanded) / static_cast<double>(state.iterations() * p.queries.size());
}

}  // namespace

#define POLYPLAN_GRID_BENCH(map)                                                                                \
  BENCHMARK_CAPTURE(Bgl, map, std::string(#map))->Name("GridAStar/bgl/" #map)->Unit(benchmark::kMillisecond);   \
  BENCHMARK_CAPTURE(Flat, map, std::string(#map))->Name("GridAStar/flat/" #map)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(Ratio, map, std::string(#map))->Name("GridAStar/ratio/" #map)->Unit(benchmark::kMillisecond)

POLYPLAN_GRID_BENCH(arena);
POLYPLAN_GRID_BENCH(den312d);
POLYPLAN_GRID_BENCH(brc202d);
POLYPLAN_GRID_BENCH(lak303d);

BENCHMARK_MAIN();
