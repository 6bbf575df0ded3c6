#include <polyplan/roadmaps/euclidean_shortest_paths.hpp>

#include <polyplan/free_space/detail/free_space_triangulation.hpp>
#include <polyplan/free_space/detail/integer_triangulation.hpp>
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/detail/free_space_frame.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/plan/thread_pool.hpp>
#include <polyplan/search/compressed_graph.hpp>
#include <polyplan/search/hub_labels.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace polyplan {
namespace {

using detail::IntegerTriangulation;
using PointLocation = IntegerTriangulation::Location;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Hub labels are built only for corner graphs of at most this mean degree. Their size follows how
// many shortest paths cross: mazes and rooms (3.7 and about 10 edges per corner on the MovingAI
// maps) get 50-140 entries per corner in seconds, while denser graphs take too long: StarCraft's
// open Aurora (42 edges per corner) 28 s for 417 entries per corner, and a field of small
// obstacles (random512: 46) had not fitted 1 GB after three minutes — there the A*, whose
// straight-line heuristic is nearly exact among small obstacles, is fast anyway.
constexpr std::size_t kLabelDegreeLimit = 16;

// The per-point corners are kept for boxes of at most this many integer points (a 4096 x 4096 map).
constexpr std::int64_t kPointTableLimit = std::int64_t{1} << 24;

double distance(const IntegerPoint& a, const IntegerPoint& b) {
  const auto dx = static_cast<double>(a.x - b.x), dy = static_cast<double>(a.y - b.y);
  return std::sqrt(dx * dx + dy * dy);
}

unsigned thread_count(unsigned asked) { return asked ? asked : std::max(1u, std::thread::hardware_concurrency()); }

struct Reached {
  int node;
  double distance;
};

}  // namespace

struct EuclideanShortestPaths::Scratch::Impl {
  IntegerTriangulation::Scratch walk;
  std::vector<int> visible, start_components, goal_components, corners;
  std::vector<IntegerPoint> path;
  std::vector<PointLocation> where;
  std::vector<Reached> from_start, from_goal;
  // A* (without a table): one record per corner, valid where its stamps equal the generation.
  struct Record {
    double cost = 0, goal_extra = 0;
    int parent = -1;
    std::uint32_t stamp = 0, goal_stamp = 0, closed = 0;
  };
  std::vector<Record> records;
  // Hub labels: the best start-to-hub cost per hub rank, through which start corner.
  std::vector<double> hub_cost;
  std::vector<int> hub_via;
  std::vector<std::uint32_t> hub_stamp;
  std::uint32_t hub_generation = 0;
  std::vector<int> to_hub;
  std::uint32_t generation = 0;
  std::vector<std::pair<double, int>> heap;
};

EuclideanShortestPaths::Scratch::Scratch() : impl_(std::make_unique<Impl>()) {
  // Room for typical queries, so that the first ones do not pay for growing.
  for (auto* v : {&impl_->visible, &impl_->start_components, &impl_->goal_components, &impl_->corners}) v->reserve(256);
  impl_->path.reserve(256);
  impl_->where.reserve(256);
  impl_->from_start.reserve(256);
  impl_->from_goal.reserve(256);
  impl_->heap.reserve(256);
}
EuclideanShortestPaths::Scratch::~Scratch() = default;
EuclideanShortestPaths::Scratch::Scratch(Scratch&&) noexcept = default;

struct EuclideanShortestPaths::Impl {
  // Whether a step of the preprocessing ran on fewer threads than it asked for (the system could
  // not start them all).
  bool short_of_threads = false;
  void note_threads(ThreadsRun run) { short_of_threads = short_of_threads || run.short_of_threads(); }
  IntegerTriangulation triangulation;
  // node_at[wedge_offset[v] + k]: the corner of free wedge k at vertex v, or -1.
  std::vector<std::size_t> wedge_offset;
  std::vector<int> node_at;
  std::vector<int> node_vertex;
  std::vector<IntegerPoint> node_point;  // node_vertex's points, beside each other for the search
  CompressedGraph graph;                 // of the corners
  // The table (n x n, row s = Dijkstra from s): distance and the predecessor on the path from s.
  std::vector<double> table_distance;
  std::vector<int> table_parent;
  // Without a table, when they fit: hub labels of the corner graph.
  std::optional<HubLabels> labels;
  // With a table or labels, the corners each integer point of the triangulated box reaches (reach()), read
  // instead of walked: for point (x, y) they are point_corners[point_begin[i] .. point_begin[i+1])
  // with i = (y - box_low.y) * box_width + (x - box_low.x).
  IntegerPoint box_low, box_high;
  std::int64_t box_width = 0;
  std::vector<std::uint32_t> point_begin;
  std::vector<int> point_corners;
  double build_seconds = 0;

  explicit Impl(IntegerTriangulation t) : triangulation(std::move(t)) {}

  std::size_t nodes() const { return node_vertex.size(); }
  const IntegerPoint& position(int node) const { return node_point[static_cast<std::size_t>(node)]; }

  // visibility_graph.cpp's arrival_node: the corner a sight line from `from` ends at when it
  // reaches vertex c, and only if it is tangent there (its continuation stays in the wedge).
  int arrival_node(std::size_t c, const IntegerPoint& from) const {
    const IntegerPoint& at = triangulation.point(c);
    const auto wedge = triangulation.wedge(c, {from.x - at.x, from.y - at.y});
    if (!wedge) return -1;
    const int node = node_at[wedge_offset[c] + *wedge];
    if (node < 0 || triangulation.wedge(c, {at.x - from.x, at.y - from.y}) != wedge) return -1;
    return node;
  }

  void build_graph(unsigned threads) {
    const std::size_t n = triangulation.vertex_count();
    wedge_offset.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) wedge_offset[v + 1] = wedge_offset[v] + triangulation.wedge_count(v);
    node_at.assign(wedge_offset[n], -1);
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < triangulation.wedge_count(v); ++k)
        if (triangulation.is_free_wedge(v, k) && triangulation.is_reflex_wedge(v, k)) {
          node_at[wedge_offset[v] + k] = static_cast<int>(node_vertex.size());
          node_vertex.push_back(static_cast<int>(v));
          node_point.push_back(triangulation.point(v));
        }
    // Each pair once (to the higher-numbered corner), from the corners' own visibility.
    std::vector<std::vector<std::tuple<int, int, double>>> found(threads);
    std::vector<IntegerTriangulation::Scratch> scratch(threads);
    std::vector<std::vector<int>> visible(threads);
    note_threads(for_each_piece(nodes(), threads, [&](std::size_t u, unsigned t) {
      const auto v = static_cast<std::size_t>(node_vertex[u]);
      std::size_t k = 0;
      while (node_at[wedge_offset[v] + k] != static_cast<int>(u)) ++k;
      visible[t].clear();
      triangulation.visible_from_corner(v, k, visible[t], scratch[t]);
      for (int c : visible[t]) {
        const int target = arrival_node(static_cast<std::size_t>(c), triangulation.point(v));
        if (target <= static_cast<int>(u)) continue;  // none, or the pair is the other's
        if (arrival_node(v, triangulation.point(static_cast<std::size_t>(c))) != static_cast<int>(u)) continue;
        found[t].emplace_back(static_cast<int>(u), target, distance(position(static_cast<int>(u)), position(target)));
      }
    }));
    std::vector<std::tuple<int, int, double>> edges;
    for (const auto& part : found) edges.insert(edges.end(), part.begin(), part.end());
    graph = CompressedGraph::from_edges(nodes(), edges);
  }

  void build_table(unsigned threads) {
    const std::size_t n = nodes();
    table_distance.assign(n * n, kInfinity);
    table_parent.assign(n * n, -1);
    std::vector<std::vector<std::pair<double, int>>> heaps(threads);
    note_threads(for_each_piece(n, threads, [&](std::size_t s, unsigned t) {
      dijkstra(graph, static_cast<int>(s), &table_distance[s * n], &table_parent[s * n], heaps[t]);
    }));
  }

  // Every integer point's reach(): the box's area times the corners each point sees (random512:
  // 87 MB in 3.6 s, which make its queries 10% faster; the small maps' queries 3 times). Only
  // for boxes of at most kPointTableLimit points, and dropped when the corners take more than
  // `max_bytes`: a world of large integer coordinates walks instead.
  void build_point_table(unsigned threads, std::size_t max_bytes) {
    IntegerPoint low = triangulation.point(0), high = low;
    for (std::size_t v = 0; v < triangulation.vertex_count(); ++v) {
      const IntegerPoint& p = triangulation.point(v);
      low = {std::min(low.x, p.x), std::min(low.y, p.y)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    const std::int64_t width = high.x - low.x + 1, rows = high.y - low.y + 1;
    if (width > kPointTableLimit / rows) return;
    box_low = low;
    box_high = high;
    box_width = width;
    std::vector<std::vector<int>> row_corners(static_cast<std::size_t>(rows));
    std::vector<std::vector<std::uint32_t>> row_counts(static_cast<std::size_t>(rows));
    std::vector<Scratch::Impl> scratch(threads);
    note_threads(for_each_piece(static_cast<std::size_t>(rows), threads, [&](std::size_t r, unsigned t) {
      std::vector<Reached> reached;
      for (std::int64_t x = box_low.x; x <= box_high.x; ++x) {
        const IntegerPoint p{x, box_low.y + static_cast<std::int64_t>(r)};
        walk_reach(p, triangulation.locate(p), reached, scratch[t]);
        for (const Reached& c : reached) row_corners[r].push_back(c.node);
        row_counts[r].push_back(static_cast<std::uint32_t>(reached.size()));
      }
    }));
    std::size_t total = 0;
    for (const auto& corners : row_corners) total += corners.size();
    if (total > max_bytes / sizeof(int) || total >= std::numeric_limits<std::uint32_t>::max()) return;
    point_begin.assign(1, 0);
    for (std::size_t r = 0; r < row_corners.size(); ++r) {
      for (std::uint32_t count : row_counts[r]) point_begin.push_back(point_begin.back() + count);
      point_corners.insert(point_corners.end(), row_corners[r].begin(), row_corners[r].end());
    }
  }

  // The corners visible from p that a taut path leaves p towards, with their distances.
  void reach(const IntegerPoint& p, const PointLocation& where, std::vector<Reached>& out, Scratch::Impl& s) const {
    if (point_begin.empty() || p.x < box_low.x || p.y < box_low.y || p.x > box_high.x || p.y > box_high.y) {
      walk_reach(p, where, out, s);
      return;
    }
    out.clear();
    const auto i = static_cast<std::size_t>((p.y - box_low.y) * box_width + (p.x - box_low.x));
    for (std::uint32_t k = point_begin[i]; k < point_begin[i + 1]; ++k)
      out.push_back({point_corners[k], distance(p, position(point_corners[k]))});
  }

  // reach() by walking the triangulation (none from a blocked point).
  void walk_reach(const IntegerPoint& p, const PointLocation& where, std::vector<Reached>& out,
                  Scratch::Impl& s) const {
    out.clear();
    s.visible.clear();
    triangulation.visible_from_point(p, where, s.visible, s.walk);
    for (int c : s.visible) {
      const int node = arrival_node(static_cast<std::size_t>(c), p);
      if (node >= 0) out.push_back({node, distance(p, position(node))});
    }
  }

  // The best corner pair through the table; corners as a path from the start's to the goal's.
  bool best_through_table(const IntegerPoint& goal, Scratch::Impl& s, std::vector<int>& corners) const {
    const std::size_t n = nodes();
    // Through corner a a path is at least ds(a) + |a goal|: taken in that order, the first a whose
    // bound reaches the best so far ends the search.
    std::vector<std::pair<double, int>>& order = s.heap;
    order.clear();
    for (std::size_t i = 0; i < s.from_start.size(); ++i)
      order.emplace_back(s.from_start[i].distance + distance(position(s.from_start[i].node), goal),
                         static_cast<int>(i));
    std::sort(order.begin(), order.end());
    std::sort(s.from_goal.begin(), s.from_goal.end(),
              [](const Reached& a, const Reached& b) { return a.node < b.node; });
    double best = kInfinity;
    int best_a = -1, best_b = -1;
    for (const auto& [bound, i] : order) {
      if (bound >= best) break;
      const Reached& a = s.from_start[static_cast<std::size_t>(i)];
      const double* row = &table_distance[static_cast<std::size_t>(a.node) * n];
      for (const Reached& b : s.from_goal) {
        const double cost = a.distance + row[b.node] + b.distance;
        if (cost < best) {
          best = cost;
          best_a = a.node;
          best_b = b.node;
        }
      }
    }
    if (best_a < 0) return false;
    corners.clear();
    const int* parent = &table_parent[static_cast<std::size_t>(best_a) * n];
    for (int x = best_b; x != best_a; x = parent[x]) corners.push_back(x);
    corners.push_back(best_a);
    std::reverse(corners.begin(), corners.end());
    return true;
  }

  // Through the hub labels: the best start-to-hub cost of every hub the start's corners know,
  // then every hub the goal's corners share with them.
  bool best_through_labels(Scratch::Impl& s, std::vector<int>& corners) const {
    const std::size_t n = nodes();
    if (s.hub_cost.size() != n) {
      s.hub_cost.assign(n, 0);
      s.hub_via.assign(n, -1);
      s.hub_stamp.assign(n, 0);
      s.hub_generation = 0;
    }
    if (++s.hub_generation == 0) {
      std::fill(s.hub_stamp.begin(), s.hub_stamp.end(), 0);
      s.hub_generation = 1;
    }
    const std::uint32_t now = s.hub_generation;
    for (const Reached& a : s.from_start)
      for (const HubLabels::Entry* e = labels->label_begin(a.node); e != labels->label_end(a.node); ++e) {
        const auto h = static_cast<std::size_t>(e->hub);
        const double cost = a.distance + e->distance;
        if (s.hub_stamp[h] != now || cost < s.hub_cost[h]) {
          s.hub_stamp[h] = now;
          s.hub_cost[h] = cost;
          s.hub_via[h] = a.node;
        }
      }
    double best = kInfinity;
    int best_hub = -1, best_b = -1;
    for (const Reached& b : s.from_goal)
      for (const HubLabels::Entry* e = labels->label_begin(b.node); e != labels->label_end(b.node); ++e) {
        const auto h = static_cast<std::size_t>(e->hub);
        if (s.hub_stamp[h] != now) continue;
        const double cost = s.hub_cost[h] + e->distance + b.distance;
        if (cost < best) {
          best = cost;
          best_hub = e->hub;
          best_b = b.node;
        }
      }
    if (best_hub < 0) return false;
    corners.clear();
    labels->path_to_hub(s.hub_via[static_cast<std::size_t>(best_hub)], best_hub, corners);  // start's corner .. hub
    s.to_hub.clear();
    labels->path_to_hub(best_b, best_hub, s.to_hub);  // goal's corner .. hub
    corners.insert(corners.end(), s.to_hub.rbegin() + 1, s.to_hub.rend());
    return true;
  }

  // Without a table: A* over the corners from every corner the start reaches, ending when the
  // best start-to-goal cost found is no more than the smallest key left.
  bool best_by_search(const IntegerPoint& goal, Scratch::Impl& s, std::vector<int>& corners) const {
    const std::size_t n = nodes();
    if (s.records.size() != n) {
      s.records.assign(n, {});
      s.generation = 0;
    }
    if (++s.generation == 0) {  // wrapped: clear for real once every 4 billion queries
      std::fill(s.records.begin(), s.records.end(), Scratch::Impl::Record{});
      s.generation = 1;
    }
    const std::uint32_t now = s.generation;
    for (const Reached& b : s.from_goal) {
      Scratch::Impl::Record& r = s.records[static_cast<std::size_t>(b.node)];
      if (r.goal_stamp != now || b.distance < r.goal_extra) r.goal_extra = b.distance;
      r.goal_stamp = now;
    }
    auto& heap = s.heap;
    heap.clear();
    auto relax = [&](int v, double cost, int from) {
      Scratch::Impl::Record& r = s.records[static_cast<std::size_t>(v)];
      if (r.stamp == now && r.cost <= cost) return;
      r.stamp = now;
      r.cost = cost;
      r.parent = from;
      heap.emplace_back(cost + distance(node_point[static_cast<std::size_t>(v)], goal), v);
      std::push_heap(heap.begin(), heap.end(), std::greater<>());
    };
    for (const Reached& a : s.from_start) relax(a.node, a.distance, -1);
    double best = kInfinity;
    int best_node = -1;
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [key, u] = heap.back();
      heap.pop_back();
      if (key >= best) break;
      const auto node = static_cast<std::size_t>(u);
      Scratch::Impl::Record& r = s.records[node];
      if (r.closed == now) continue;
      r.closed = now;
      if (r.goal_stamp == now && r.cost + r.goal_extra < best) {
        best = r.cost + r.goal_extra;
        best_node = u;
      }
      const double cost = r.cost;
      for (std::size_t e = graph.row_begin(u); e < graph.row_end(u); ++e)
        relax(graph.adjacent[e], cost + graph.weight[e], u);
    }
    if (best_node < 0) return false;
    corners.clear();
    for (int x = best_node; x >= 0; x = s.records[static_cast<std::size_t>(x)].parent) corners.push_back(x);
    std::reverse(corners.begin(), corners.end());
    return true;
  }
};

EuclideanShortestPaths::EuclideanShortestPaths(const CSpace& cspace, EuclideanShortestPathsOptions options) {
  const Stopwatch building;
  std::optional<IntegerTriangulation> triangulation;
  {
    const detail::FreeSpaceTriangulation exact(detail::CSpaceAccess::impl(cspace), query_points(cspace.world()));
    triangulation = IntegerTriangulation::from(exact);
  }
  if (!triangulation)
    throw std::invalid_argument(cspace.world().source +
                                ": the free space has a corner that is not an integer point below 2^30 in magnitude");
  impl_ = std::make_unique<Impl>(std::move(*triangulation));
  build(options);
  impl_->build_seconds = building.seconds();
}

EuclideanShortestPaths::EuclideanShortestPaths(const GridMap& map, EuclideanShortestPathsOptions options) {
  const Stopwatch building;
  impl_ = std::make_unique<Impl>(IntegerTriangulation::from_grid(map));
  build(options);
  impl_->build_seconds = building.seconds();
}

void EuclideanShortestPaths::build(EuclideanShortestPathsOptions options) {
  const unsigned threads = thread_count(options.threads);
  impl_->build_graph(threads);
  const std::size_t n = impl_->nodes();
  if (n > 0 && n <= options.table_bytes / (sizeof(double) + sizeof(int)) / n) impl_->build_table(threads);
  else if (n > 0 && impl_->graph.adjacent.size() <= kLabelDegreeLimit * n)
    impl_->labels = HubLabels::build(impl_->graph, options.label_bytes);
  if (n > 0) impl_->build_point_table(threads, options.table_bytes);
}

EuclideanShortestPaths::~EuclideanShortestPaths() = default;
EuclideanShortestPaths::EuclideanShortestPaths(EuclideanShortestPaths&&) noexcept = default;
EuclideanShortestPaths& EuclideanShortestPaths::operator=(EuclideanShortestPaths&&) noexcept = default;

std::size_t EuclideanShortestPaths::corner_count() const { return impl_->nodes(); }
std::size_t EuclideanShortestPaths::edge_count() const { return impl_->graph.adjacent.size() / 2; }
bool EuclideanShortestPaths::has_table() const { return !impl_->table_distance.empty(); }
bool EuclideanShortestPaths::has_labels() const { return impl_->labels.has_value(); }
std::size_t EuclideanShortestPaths::label_entries() const { return impl_->labels ? impl_->labels->entry_count() : 0; }
double EuclideanShortestPaths::build_seconds() const { return impl_->build_seconds; }
bool EuclideanShortestPaths::short_of_threads() const { return impl_->short_of_threads; }

std::size_t EuclideanShortestPaths::memory_bytes() const {
  const Impl& g = *impl_;
  return g.triangulation.memory_bytes() + (g.wedge_offset.capacity() + g.graph.begin.capacity()) * sizeof(std::size_t) +
         g.node_point.capacity() * sizeof(IntegerPoint) +
         (g.node_at.capacity() + g.node_vertex.capacity() + g.graph.adjacent.capacity() + g.table_parent.capacity() +
          g.point_corners.capacity() + g.point_begin.capacity()) *
             sizeof(int) +
         (g.graph.weight.capacity() + g.table_distance.capacity()) * sizeof(double) +
         (g.labels ? g.labels->memory_bytes() : 0);
}

EuclideanPathAnswer EuclideanShortestPaths::query(const IntegerPoint& start, const IntegerPoint& goal,
                                                  Scratch& scratch) const {
  const Impl& g = *impl_;
  Scratch::Impl& s = *scratch.impl_;
  EuclideanPathAnswer answer;
  const auto fits = [](const IntegerPoint& p) {
    return std::abs(p.x) < detail::kIntegerCoordinateLimit && std::abs(p.y) < detail::kIntegerCoordinateLimit;
  };
  const IntegerPoint from{start.x, start.y}, to{goal.x, goal.y};
  const PointLocation start_at = fits(start) ? g.triangulation.locate(from) : PointLocation{};
  const PointLocation goal_at = fits(goal) ? g.triangulation.locate(to) : PointLocation{};
  g.triangulation.components_at(start_at, s.start_components);
  g.triangulation.components_at(goal_at, s.goal_components);
  auto named = [](const char* what, const IntegerPoint& p) {
    return std::string(what) + " " + detail::to_text(p) + " is not in the free space";
  };
  if (s.start_components.empty()) {
    answer.why_not = named("the start", from);
    return answer;
  }
  if (s.goal_components.empty()) {
    answer.why_not = named("the goal", to);
    return answer;
  }
  const bool shared = std::any_of(s.start_components.begin(), s.start_components.end(), [&](int c) {
    return std::find(s.goal_components.begin(), s.goal_components.end(), c) != s.goal_components.end();
  });
  if (!shared) {
    answer.why_not = "start and goal lie in different components of the free space";
    return answer;
  }
  std::vector<IntegerPoint>& path = s.path;
  std::vector<PointLocation>& where = s.where;
  path.assign(1, from);
  where.assign(1, start_at);
  if (!g.triangulation.segment_free(from, start_at, to)) {  // start does not see goal: through corners
    g.reach(from, start_at, s.from_start, s);
    g.reach(to, goal_at, s.from_goal, s);
    const bool found = has_table() ? g.best_through_table(to, s, s.corners)
                       : g.labels  ? g.best_through_labels(s, s.corners)
                                   : g.best_by_search(to, s, s.corners);
    if (!found) {  // cannot happen: one component means one path through its corners
      answer.why_not = "no path through the corners between start and goal";
      return answer;
    }
    for (int c : s.corners) {
      path.push_back(g.position(c));
      where.push_back(
          IntegerTriangulation::at_vertex(static_cast<std::size_t>(g.node_vertex[static_cast<std::size_t>(c)])));
    }
    // Every reported path is checked exactly by the segment walk, which is not the visibility
    // that found it; a failure is a bug, never a tolerance call.
    path.push_back(to);
    where.push_back(goal_at);
    if (!g.triangulation.path_free(path, where))
      throw std::logic_error(
          "euclidean shortest paths produced an invalid path: " +
          g.triangulation.why_path_blocked(path, where).value_or("(the check disagrees with itself)"));
  } else {
    path.push_back(to);
  }
  answer.found = true;
  answer.path.reserve(path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i > 0) answer.length += distance(path[i - 1], path[i]);
    if (i == 0 || !(path[i] == path[i - 1])) answer.path.push_back({path[i].x, path[i].y});
  }
  return answer;
}

std::vector<TimedPathAnswer> answer_all(const EuclideanShortestPaths& paths,
                                        const std::vector<std::pair<IntegerPoint, IntegerPoint>>& queries,
                                        unsigned threads, const std::function<void(std::size_t done)>& progress,
                                        bool* short_of_threads) {
  std::vector<TimedPathAnswer> answers(queries.size());
  std::atomic<std::size_t> next{0}, done{0};
  auto work = [&](unsigned worker) {
    const bool reports = worker == 0;
    EuclideanShortestPaths::Scratch scratch;
    for (std::size_t i; (i = next.fetch_add(1)) < queries.size();) {
      const Stopwatch clock;
      answers[i].answer = paths.query(queries[i].first, queries[i].second, scratch);
      answers[i].us = clock.seconds() * 1e6;
      const std::size_t finished = done.fetch_add(1) + 1;
      if (reports && progress && finished < queries.size()) progress(finished);  // the last comes once, below
    }
  };
  const ThreadsRun ran = run_on_threads(thread_count(threads), work);
  if (short_of_threads) *short_of_threads = ran.short_of_threads();
  if (progress) progress(queries.size());
  return answers;
}

}  // namespace polyplan
