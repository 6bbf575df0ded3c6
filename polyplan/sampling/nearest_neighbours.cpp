// Nearest neighbours by a linear scan while there are few points, then on nanoflann's dynamic
// KD-tree: a family of static trees of 1, 2, 4, ... points, two of which are merged and rebuilt as
// points arrive (amortised O(log² n) an add); a query searches every tree.
//
// The tree is built from every point at once when size() reaches scan_threshold(dimension): below
// it a scan of contiguous coordinates is faster (bench/nearest_neighbours_race.cpp --marginal,
// docs/nearest_neighbours.md), the more so in higher dimensions, where the tree prunes little,
// least on the torus (see below). Scan and tree report the same distances, so answers do not
// depend on which one gave them.
//
// A KD-tree cuts the torus coordinates [0, 2π) as if they were a line, so its pruning must be
// redone for the circle. nanoflann prunes a subtree when the sum over coordinates of
// accum_dist(q_i, cut_i) exceeds the worst distance kept, where the subtree lies wholly on the far
// side of cut_i (a split value, or the edge of a tree's box). On the circle a point on the far
// side [cut, 2π) of q < cut is at least min(cut − q, q) away (straight up to the cut, or down
// through 0 and round), and one on the far side [0, cut] of q > cut at least
// min(q − cut, 2π − q). These are lower bounds per coordinate, the torus distance is the sum of
// the per-coordinate distances, so their sum bounds it and no subtree holding a nearer point is
// pruned. (nanoflann's SO2_Adaptor measures the short way to the cut itself, which bounds nothing:
// a point beyond the cut can be nearer across the seam.)
#include <polyplan/sampling/nearest_neighbours.hpp>

#include <polyplan/sampling/detail/scan_distance.hpp>

#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace polyplan {
namespace {

// The dataset nanoflann reads: point i's coordinates at [i·dimension, (i + 1)·dimension).
struct Points {
  std::size_t dimension;
  std::vector<double> coordinates;

  std::size_t kdtree_get_point_count() const { return coordinates.size() / dimension; }
  double kdtree_get_pt(std::size_t index, std::size_t coordinate) const {
    return coordinates[index * dimension + coordinate];
  }
  const double* point(std::size_t index) const { return coordinates.data() + index * dimension; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;  // nanoflann computes each tree's box from its points
  }
};

// Below this many points the scan answers, from it on the tree. Measured for nearest(q) as the
// cost of a (query + add) while the points grow from n to 2n (docs/nearest_neighbours.md), the two
// cross at about 250 points in 2-D, 350 to 700 in 3-D, 2000 in 4-D and 5000 to 6000 in 6-D; for
// nearest(q, k) and within(q, r) the scan stays ahead longer. 5-D, not measured, is put between
// its neighbours, 1-D with 2-D, and above 6-D, where the tree can only prune less, with 6-D.
std::size_t scan_threshold(std::size_t dimension) {
  constexpr std::array<std::size_t, 7> by_dimension{0, 250, 250, 500, 2000, 4000, 6000};
  return by_dimension[std::clamp<std::size_t>(dimension, 1, by_dimension.size() - 1)];
}

template <class T, class DataSource, class AccessorType>
struct TorusDistance {
  using ElementType = T;
  using DistanceType = T;

  const DataSource& data_source;

  explicit TorusDistance(const DataSource& source) : data_source(source) {}

  // Point to point: sampling_distance's torus sum bit for bit, but without normalize_angle's fmod
  // (two an angle: four fifths of a query's time in 6D). On [0, 2π), where check() keeps every
  // coordinate, normalize_angle is the identity and angular_distance(a, b) is min(e, 2π − e) for
  // e = |b − a|, its shift by 2π being exact (Sterbenz). Debug builds assert it.
  DistanceType evalMetric(const T* a, AccessorType b, std::size_t size) const {
    const T* p = data_source.point(b);
    const DistanceType sum = detail::scan_distance<SamplingMetric::torus>(a, p, size);
    assert(sum == sampling_distance(SamplingMetric::torus, std::span(a, size), std::span(p, size)));
    return sum;
  }
  // Query coordinate to a cut: the lower bound of the top comment, never the distance to the cut.
  template <class U, class V>
  DistanceType accum_dist(U value, V cut, std::size_t) const {
    return value < cut ? std::min<DistanceType>(cut - value, value)
                       : std::min<DistanceType>(value - cut, two_pi - value);
  }
};

struct metric_torus : nanoflann::Metric {
  template <class T, class DataSource, class AccessorType = std::uint32_t>
  struct traits {
    using distance_t = TorusDistance<T, DataSource, AccessorType>;
  };
};

template <class Metric>
using Tree =
    nanoflann::KDTreeSingleIndexDynamicAdaptor<typename Metric::template traits<double, Points>::distance_t, Points>;
using AnyTree = std::variant<Tree<nanoflann::metric_L2_Simple>, Tree<metric_torus>>;

// The dynamic index's "maximum point count" fixes its number of trees, floor(log2(maximum)) + 1,
// which hold 2^trees − 1 points in all; it does not grow, and indexes past its array of trees after
// that. 2^31 gives 32 trees, 2^32 − 1 points, as many as its 32-bit point indices number; an empty
// tree costs a query one test.
constexpr std::size_t maximum_hint = std::size_t{1} << 31;
constexpr std::size_t capacity = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t leaf_size = 10;

// nanoflann prunes when its running sum of bounds exceeds the worst distance kept, but sums in
// another order than evalMetric, so rounding could put a bound a few ulps above a distance it
// bounds. The result sets report their worst distance widened by far more than that (relatively,
// plus 1e-9 a coordinate on the torus, whose bounds are at most π each, or DBL_MIN in the plane for
// subnormal squares), so pruning never rests on rounding; what is kept is decided on the exact
// distances.
double widened(double worst, double absolute) { return worst + worst * 1e-9 + absolute; }

// The k nearest, nearest first: nanoflann's insertion-sorted KNNResultSet, seen through the widened
// worst distance.
class NearestResults {
 public:
  using DistanceType = double;
  using IndexType = std::size_t;

  NearestResults(std::size_t k, std::size_t* indices, double* distances, double slack) : results_(k), slack_(slack) {
    results_.init(indices, distances);
  }
  bool addPoint(double distance, std::size_t index) { return results_.addPoint(distance, index); }
  double worstDist() const { return widened(results_.worstDist(), slack_); }
  bool full() const { return results_.full(); }

 private:
  nanoflann::KNNResultSet<double, std::size_t> results_;
  double slack_;
};

// Every point at tree distance <= limit. (nanoflann's RadiusResultSet keeps distance < radius only.)
class WithinResults {
 public:
  using DistanceType = double;
  using IndexType = std::size_t;

  WithinResults(double limit, double slack, std::vector<std::pair<double, std::size_t>>& found)
      : limit_(limit), searched_(widened(limit, slack)), found_(found) {}
  bool addPoint(double distance, std::size_t index) {
    if (distance <= limit_) found_.emplace_back(distance, index);
    return true;
  }
  double worstDist() const { return searched_; }
  bool full() const { return true; }

 private:
  double limit_;
  double searched_;
  std::vector<std::pair<double, std::size_t>>& found_;
};

// The largest s with √s <= radius: the tree's squared distances s then satisfy s <= it exactly
// when sampling_distance's √s <= radius (sqrt is correctly rounded, hence monotone).
double largest_square_within(double radius) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double limit = radius * radius;
  while (limit > 0 && std::sqrt(limit) > radius) limit = std::nextafter(limit, 0.0);
  while (limit < infinity && std::sqrt(std::nextafter(limit, infinity)) <= radius)
    limit = std::nextafter(limit, infinity);
  return limit;
}

// A tree over every point so far: the dynamic index's constructor adds the points already in its
// dataset, all in one pass.
void build_tree(SamplingMetric metric, const Points& points, std::optional<AnyTree>& tree) {
  const nanoflann::KDTreeSingleIndexAdaptorParams params(leaf_size);
  const int dimension = static_cast<int>(points.dimension);
  if (metric == SamplingMetric::torus)
    tree.emplace(std::in_place_type<Tree<metric_torus>>, dimension, points, params, maximum_hint);
  else tree.emplace(std::in_place_type<Tree<nanoflann::metric_L2_Simple>>, dimension, points, params, maximum_hint);
}

}  // namespace

struct NearestNeighbours::Impl {
  SamplingMetric metric;
  Points points;
  double slack;           // widened()'s absolute part
  std::size_t tree_from;  // scan_threshold(dimension)
  // Empty until size() reaches tree_from. Reads `points`; Impl stays where it was made (moves move
  // the pointer).
  std::optional<AnyTree> tree;

  Impl(std::size_t dimension, SamplingMetric metric)
      : metric(metric), points{dimension, {}},
        slack(metric == SamplingMetric::torus ? 1e-9 * static_cast<double>(dimension)
                                              : std::numeric_limits<double>::min()),
        tree_from(scan_threshold(dimension)) {}

  std::size_t size() const { return points.coordinates.size() / points.dimension; }

  // Also rejects what would break the tree's order or the torus bounds: coordinates that are not
  // finite, or torus coordinates outside [0, 2π).
  void check(std::span<const double> point, const char* function) const {
    const auto reject = [&](const std::string& why) {
      throw std::invalid_argument(std::string("NearestNeighbours::") + function + ": " + why);
    };
    if (point.size() != points.dimension)
      reject(std::to_string(point.size()) + " coordinates, expected " + std::to_string(points.dimension));
    for (const double c : point) {
      if (!std::isfinite(c)) reject("a coordinate is not finite");
      if (metric == SamplingMetric::torus && !(c >= 0 && c < two_pi))
        reject("torus coordinate " + std::to_string(c) + " is outside [0, 2π)");
    }
  }

  void add_last_point() {
    if (tree) {
      const auto accessor = static_cast<std::uint32_t>(size() - 1);
      std::visit([&](auto& forest) { forest.addPoints(accessor, accessor); }, *tree);
    } else if (size() >= tree_from) {
      build_tree(metric, points, tree);
    }
  }

  // Results take every point offered and keep what they want (nearest, or within the radius), so
  // the scan offers them all.
  template <class Results>
  void search(std::span<const double> query, Results& results) const {
    if (tree) return search_trees(query, results);
    detail::with_scan_distance(metric, points.dimension, [&](auto distance) {
      const double* p = points.coordinates.data();
      for (std::size_t i = 0, n = size(); i < n; ++i, p += points.dimension)
        results.addPoint(distance(query.data(), p, points.dimension), i);
    });
  }

  template <class Results>
  void search_trees(std::span<const double> query, Results& results) const {
    std::visit(
        [&](const auto& forest) {
          // Largest tree first: its points tighten the worst distance before the small trees are
          // searched (a fifth to a third fewer points measured than the dynamic index's own
          // findNeighbors, which goes smallest first).
          const auto& trees = forest.getAllIndices();
          for (auto t = trees.rbegin(); t != trees.rend(); ++t)
            t->findNeighbors(results, query.data(), nanoflann::SearchParams());
        },
        *tree);
  }
};

NearestNeighbours::NearestNeighbours(std::size_t dimension, SamplingMetric metric) {
  if (dimension == 0) throw std::invalid_argument("NearestNeighbours: dimension 0");
  impl_ = std::make_unique<Impl>(dimension, metric);
}

NearestNeighbours::~NearestNeighbours() = default;
NearestNeighbours::NearestNeighbours(NearestNeighbours&&) noexcept = default;
NearestNeighbours& NearestNeighbours::operator=(NearestNeighbours&&) noexcept = default;

std::size_t NearestNeighbours::dimension() const { return impl_->points.dimension; }
std::size_t NearestNeighbours::size() const { return impl_->size(); }

std::span<const double> NearestNeighbours::point(std::size_t index) const {
  if (index >= size())
    throw std::out_of_range("NearestNeighbours::point: index " + std::to_string(index) + " of " +
                            std::to_string(size()));
  return {impl_->points.point(index), dimension()};
}

std::size_t NearestNeighbours::add(std::span<const double> point) {
  impl_->check(point, "add");
  const std::size_t index = size();
  if (index == capacity) throw std::length_error("NearestNeighbours::add: the tree is full");
  impl_->points.coordinates.insert(impl_->points.coordinates.end(), point.begin(), point.end());
  impl_->add_last_point();
  return index;
}

std::size_t NearestNeighbours::nearest(std::span<const double> query) const {
  impl_->check(query, "nearest");
  if (size() == 0) throw std::logic_error("NearestNeighbours::nearest: no points");
  std::size_t index = 0;
  double distance = 0;
  NearestResults results(1, &index, &distance, impl_->slack);
  impl_->search(query, results);
  return index;
}

void NearestNeighbours::nearest(std::span<const double> query, std::size_t k, std::vector<std::size_t>& out) const {
  impl_->check(query, "nearest");
  // Until k points are kept the worst distance is infinite and nothing is pruned, so all of `out`
  // is filled.
  out.resize(std::min(k, size()));
  if (out.empty()) return;
  std::vector<double> distances(out.size());
  NearestResults results(out.size(), out.data(), distances.data(), impl_->slack);
  impl_->search(query, results);
}

void NearestNeighbours::within(std::span<const double> query, double radius, std::vector<std::size_t>& out) const {
  impl_->check(query, "within");
  out.clear();
  if (!(radius >= 0)) return;  // nothing is within a negative (or NaN) radius
  const double limit = impl_->metric == SamplingMetric::torus ? radius : largest_square_within(radius);
  std::vector<std::pair<double, std::size_t>> found;
  WithinResults results(limit, impl_->slack, found);
  impl_->search(query, results);
  std::sort(found.begin(), found.end());
  out.reserve(found.size());
  for (const auto& [distance, index] : found) out.push_back(index);
}

}  // namespace polyplan
