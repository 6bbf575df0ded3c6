// The sampling planners' nearest-neighbour index against a linear scan (docs/nearest_neighbours.md):
// a plain program. Each run grows an index from empty to N uniformly random points as RRT does, one
// query before every add, and reports the CPU time per (query + add) pair, the least of a few runs.
// Three queries are raced, each in its own run: nearest(q) (RRT), nearest(q, 10) (RRT*, PRM) and
// within(q, r) with r holding about 15 points (RRT*'s shrinking ball). Every answer of every run is
// then checked against brute force under sampling_distance (the same distances, ties aside).
//
//   nearest_neighbours_race [--sizes 100,300,...] [--marginal] [--no-check]
//
// "index" is polyplan's NearestNeighbours, "scan" a linear scan over contiguous coordinates.
// --marginal times the growth from n to 2n points instead of from 1 to N: the cost at about n
// points, where the two cross being the index's threshold between them. --no-check skips the
// brute-force check (quadratic in N).
#include <polyplan/sampling/detail/scan_distance.hpp>
#include <polyplan/sampling/nearest_neighbours.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <time.h>

using namespace polyplan;

namespace {

constexpr std::size_t k_nearest = 10;
constexpr double points_within = 15;   // expected points in a within() ball
constexpr double euclidean_side = 10;  // Euclidean points in [0, 10)²

using detail::with_scan_distance;  // the index's own scan distance (sampling/detail/scan_distance.hpp)

// A linear scan: the peer the index is raced against. Every distance is summed in full: stopping
// once a partial sum exceeds the worst kept was measured 2 to 2.5 times slower in 4-D and 6-D
// (a mispredicted branch a coordinate costs more than the coordinates it skips).
class LinearScan {
 public:
  LinearScan(std::size_t dimension, SamplingMetric metric) : dimension_(dimension), metric_(metric) {}

  std::size_t size() const { return coordinates_.size() / dimension_; }
  std::size_t add(std::span<const double> point) {
    coordinates_.insert(coordinates_.end(), point.begin(), point.end());
    return size() - 1;
  }
  std::span<const double> coordinates() const { return coordinates_; }

  std::size_t nearest(std::span<const double> query) const {
    return with_scan_distance(metric_, dimension_, [&](auto distance) {
      double best = std::numeric_limits<double>::infinity();
      std::size_t best_index = 0;
      const double* p = coordinates_.data();
      for (std::size_t i = 0, n = size(); i < n; ++i, p += dimension_) {
        const double d = distance(p, query.data(), dimension_);
        if (d < best) best = d, best_index = i;
      }
      return best_index;
    });
  }
  void nearest(std::span<const double> query, std::size_t k, std::vector<std::size_t>& out) const {
    ranked_.clear();
    with_scan_distance(metric_, dimension_, [&](auto distance) {
      double worst = std::numeric_limits<double>::infinity();
      const double* p = coordinates_.data();
      for (std::size_t i = 0, n = size(); i < n; ++i, p += dimension_) {
        const double d = distance(p, query.data(), dimension_);
        if (d >= worst) continue;
        ranked_.insert(std::upper_bound(ranked_.begin(), ranked_.end(), std::pair(d, i)), std::pair(d, i));
        if (ranked_.size() > k) ranked_.pop_back();
        if (ranked_.size() == k) worst = ranked_.back().first;
      }
    });
    out.clear();
    for (const auto& [d, i] : ranked_) out.push_back(i);
  }
  void within(std::span<const double> query, double radius, std::vector<std::size_t>& out) const {
    // Euclidean sums are squares: compare them with the radius squared (close enough for a race;
    // the library's within() handles the rounding at the radius).
    const double limit = metric_ == SamplingMetric::torus ? radius : radius * radius;
    ranked_.clear();
    with_scan_distance(metric_, dimension_, [&](auto distance) {
      const double* p = coordinates_.data();
      for (std::size_t i = 0, n = size(); i < n; ++i, p += dimension_) {
        const double d = distance(p, query.data(), dimension_);
        if (d <= limit) ranked_.emplace_back(d, i);
      }
    });
    std::sort(ranked_.begin(), ranked_.end());
    out.clear();
    for (const auto& [d, i] : ranked_) out.push_back(i);
  }

 private:
  std::size_t dimension_;
  SamplingMetric metric_;
  std::vector<double> coordinates_;
  mutable std::vector<std::pair<double, std::size_t>> ranked_;
};

enum class Query { nearest, k_nearest, within };

struct Space {
  std::size_t dimension;
  SamplingMetric metric;
  std::string name() const {
    return std::to_string(dimension) + "-D " + (metric == SamplingMetric::torus ? "torus" : "euclidean");
  }
};

using Point = std::vector<double>;

// The same N points and queries for every index: 2N uniform points, alternately added and queried.
std::vector<Point> uniform_points(const Space& space, std::size_t count, std::uint64_t seed) {
  SamplingRandom random(seed);
  const double side = space.metric == SamplingMetric::torus ? two_pi : euclidean_side;
  std::vector<Point> points(count, Point(space.dimension));
  for (Point& p : points)
    for (double& c : p) c = side * uniform01(random);
  return points;
}

// The radius whose ball holds `points_within` of n uniform points on average: an L1 ball of radius
// r has volume (2r)^d / d! on the torus, a disc πr² in the plane.
double within_radius(const Space& space, std::size_t n) {
  const double fraction = std::min(1.0, points_within / static_cast<double>(std::max<std::size_t>(n, 1)));
  if (space.metric == SamplingMetric::euclidean) return euclidean_side * std::sqrt(fraction / M_PI);
  const double d = static_cast<double>(space.dimension);
  return M_PI * std::pow(fraction * std::tgamma(d + 1), 1 / d);
}

// The CPU time of this thread: on a shared machine the wall clock also counts the time others ran.
double thread_cpu_nanoseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e9 * static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec);
}

struct Run {
  double nanoseconds_per_pair;
  std::vector<std::vector<std::size_t>> answers;  // query i's, asked with i points in the index
};

// Adds points[0, from) untimed, then times a query before each add of points[from, end).
template <class Index>
Run race(const Space& space, Query query, const std::vector<Point>& points, const std::vector<Point>& queries,
         const std::function<Index()>& make, int repetitions, std::size_t from = 1) {
  Run run{std::numeric_limits<double>::infinity(), std::vector<std::vector<std::size_t>>(points.size())};
  std::vector<std::size_t> out;
  for (int r = 0; r < repetitions; ++r) {
    Index index = make();
    for (std::size_t i = 0; i < from; ++i) index.add(points[i]);
    const double start = thread_cpu_nanoseconds();
    for (std::size_t i = from; i < points.size(); ++i) {
      switch (query) {
        case Query::nearest: out.assign(1, index.nearest(queries[i])); break;
        case Query::k_nearest: index.nearest(queries[i], k_nearest, out); break;
        case Query::within: index.within(queries[i], within_radius(space, i), out); break;
      }
      if (r == 0) run.answers[i] = out;
      index.add(points[i]);
    }
    const double elapsed = thread_cpu_nanoseconds() - start;
    run.nanoseconds_per_pair = std::min(run.nanoseconds_per_pair, elapsed / double(points.size() - from));
  }
  return run;
}

// Brute force for query i over points [0, i): every distance, and the distances the answer must
// have, in order. (The scan's Euclidean within() compares squares with the radius squared, which
// could differ from the square root's verdict within a rounding of the radius: never met with
// random points.)
struct BruteForce {
  std::vector<double> distance;
  std::vector<double> expected;
};

BruteForce brute_force(const Space& space, Query query, const std::vector<Point>& points,
                       const std::vector<Point>& queries, std::size_t i) {
  BruteForce truth{std::vector<double>(i), {}};
  for (std::size_t j = 0; j < i; ++j) truth.distance[j] = sampling_distance(space.metric, points[j], queries[i]);
  if (query == Query::within) {
    const double radius = within_radius(space, i);
    std::copy_if(truth.distance.begin(), truth.distance.end(), std::back_inserter(truth.expected),
                 [&](double d) { return d <= radius; });
    std::sort(truth.expected.begin(), truth.expected.end());
  } else {
    truth.expected = truth.distance;
    const std::size_t k = std::min(i, query == Query::nearest ? std::size_t{1} : k_nearest);
    std::partial_sort(truth.expected.begin(), truth.expected.begin() + k, truth.expected.end());
    truth.expected.resize(k);
  }
  return truth;
}

// The same distances as brute force, in order: right up to the order of ties.
bool matches(const BruteForce& truth, const std::vector<std::size_t>& answer) {
  if (answer.size() != truth.expected.size()) return false;
  for (std::size_t j = 0; j < answer.size(); ++j)
    if (answer[j] >= truth.distance.size() || truth.distance[answer[j]] != truth.expected[j]) return false;
  return true;
}

// For each run, how many of its answers differ from brute force.
std::vector<std::size_t> wrong_answers(const Space& space, Query query, const std::vector<Point>& points,
                                       const std::vector<Point>& queries, const std::vector<const Run*>& runs,
                                       std::size_t from) {
  std::vector<std::size_t> wrong(runs.size());
  for (std::size_t i = from; i < points.size(); ++i) {
    const BruteForce truth = brute_force(space, query, points, queries, i);
    for (std::size_t r = 0; r < runs.size(); ++r) wrong[r] += !matches(truth, runs[r]->answers[i]);
  }
  return wrong;
}

// Few repetitions of the big runs, more of the small ones whose times are short and noisy.
int repetitions_for(std::size_t n) { return static_cast<int>(std::clamp<std::size_t>(20000 / n, 3, 50)); }

std::vector<std::size_t> parse_sizes(const char* text) {
  std::vector<std::size_t> sizes;
  for (const char* p = text; *p;) {
    char* end = nullptr;
    sizes.push_back(std::strtoul(p, &end, 10));
    p = *end == ',' ? end + 1 : end;
  }
  return sizes;
}

const std::vector<Space> spaces{{2, SamplingMetric::euclidean},
                                {2, SamplingMetric::torus},
                                {3, SamplingMetric::torus},
                                {4, SamplingMetric::torus},
                                {6, SamplingMetric::torus}};

// The table: nanoseconds per (query + add) pair for each index, and any wrong answers. Grown from
// 1 to N points, or (marginal) from n to 2n: one doubling, so that the dynamic tree's merges are
// paid in their average share, and where scan and index cross is the threshold.
int print_race(const std::vector<std::size_t>& sizes, bool marginal, bool check) {
  std::printf("| space | %s | query | index (ns) | scan (ns) |\n|---|---|---|---|---|\n", marginal ? "n → 2n" : "N");
  int failures = 0;
  for (const Space& space : spaces) {
    for (const std::size_t n : sizes) {
      const std::size_t from = marginal ? n : 1;
      const std::size_t end = marginal ? 2 * n : n;
      const std::vector<Point> points = uniform_points(space, end, 1);
      const std::vector<Point> queries = uniform_points(space, end, 2);
      for (const Query query : {Query::nearest, Query::k_nearest, Query::within}) {
        const int repetitions = repetitions_for(end);
        const Run index = race<NearestNeighbours>(
            space, query, points, queries, [&] { return NearestNeighbours(space.dimension, space.metric); },
            repetitions, from);
        const Run scan = race<LinearScan>(
            space, query, points, queries, [&] { return LinearScan(space.dimension, space.metric); }, repetitions,
            from);
        const char* names[] = {"nearest", "10 nearest", "within"};
        std::printf("| %s | %zu | %s | %.0f | %.0f |\n", space.name().c_str(), n, names[static_cast<int>(query)],
                    index.nanoseconds_per_pair, scan.nanoseconds_per_pair);
        if (check) {
          const std::vector<std::size_t> wrong = wrong_answers(space, query, points, queries, {&index, &scan}, from);
          const char* indexes[] = {"index", "scan"};
          for (std::size_t r = 0; r < wrong.size(); ++r) {
            if (wrong[r]) std::printf("  WRONG: %s gave %zu answers unlike brute force\n", indexes[r], wrong[r]);
            failures += wrong[r] != 0;
          }
        }
        std::fflush(stdout);
      }
    }
  }
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes{100, 300, 1000, 3000, 10000, 30000};
  bool marginal = false;
  bool check = true;
  for (int a = 1; a < argc; ++a) {
    const std::string option = argv[a];
    if (option == "--sizes" && a + 1 < argc) {
      sizes = parse_sizes(argv[++a]);
    } else if (option == "--marginal") {
      marginal = true;
    } else if (option == "--no-check") {
      check = false;
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...] [--marginal] [--no-check]\n", argv[0]);
      return 2;
    }
  }
  return print_race(sizes, marginal, check) == 0 ? 0 : 1;
}
