#include <polyplan/sampling/polygon_sampling_space.hpp>

#include <polyplan/free_space/detail/free_space_triangulation.hpp>
#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/sampling/detail/sampling_box.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {
namespace {

using Box = detail::SamplingBox;

// The region samples are drawn from (see the header).
Box sampling_box(const CSpace& cspace) {
  Box box;
  if (const auto& reference = cspace.reference_box()) {
    box.add({reference->xmin, reference->ymin});
    box.add({reference->xmax, reference->ymax});
    return box;
  }
  for (const PolygonWithHoles& c : cspace.cobstacles())
    for (const ExactPoint& p : c.outer) box.add(p);
  for (const Query& q : cspace.world().queries) box.add(q.start), box.add(q.goal);
  box.grow_for_unbounded();
  return box;
}

// The corners of the box, which the triangulation's frame must hold in a world without bounds.
std::vector<ExactPoint> corners(const Box& box) {
  if (box.empty()) return {};
  return {{Rational(box.xmin), Rational(box.ymin)}, {Rational(box.xmax), Rational(box.ymax)}};
}

// What a milestone or tree node keeps (SamplingSpace::free_region): its point in the kernel's type,
// converted from the exact rationals once, and the triangle it lies in, located once; beyond the
// triangulation's frame only the point. Motions from it walk from there: the same exact walk, none
// of the conversion and location it would repeat.
struct PolygonFreeRegion final : FreeRegion {
  detail::Point point;
  std::shared_ptr<const detail::FreeSpaceTriangulation::Place> place;  // null beyond the frame
};

const PolygonFreeRegion* polygon_region(const FreeRegion* region) {
  return static_cast<const PolygonFreeRegion*>(region);  // this space made it, or it is null
}

// Tests run on the free space's constrained triangulation (a walk with exact orientation
// predicates, microseconds), and on the C-space's arrangement (geometry/path_check.hpp, the same
// verdicts, much slower) for a configuration beyond the triangulation's frame.
class PolygonSamplingSpace final : public SamplingSpace<TranslatingRobot> {
 public:
  explicit PolygonSamplingSpace(const CSpace& cspace)
      : cspace_(&cspace), box_(sampling_box(cspace)),
        triangulation_(detail::CSpaceAccess::impl(cspace), corners(box_)) {}

  std::size_t dimension() const override { return 2; }
  SamplingMetric metric() const override { return SamplingMetric::euclidean; }
  double extent() const override { return box_.empty() ? 0 : std::hypot(box_.xmax - box_.xmin, box_.ymax - box_.ymin); }
  double volume() const override { return box_.empty() ? 0 : (box_.xmax - box_.xmin) * (box_.ymax - box_.ymin); }

  void sample(SamplingRandom& random, std::span<double> out) const override {
    out[0] = box_.xmin + uniform01(random) * (box_.xmax - box_.xmin);
    out[1] = box_.ymin + uniform01(random) * (box_.ymax - box_.ymin);
  }
  std::optional<std::string> outside(std::span<const double> c) const override { return box_.outside(c); }
  void coordinates(const ExactPoint& p, std::span<double> out) const override {
    out[0] = to_double(p.x);
    out[1] = to_double(p.y);
  }
  ExactPoint configuration(std::span<const double> c) const override { return {Rational(c[0]), Rational(c[1])}; }

  bool is_free(const ExactPoint& p) override {
    if (!triangulation_.in_frame(p)) return cspace_->locate(p).kind != Location::Kind::blocked;
    return !triangulation_.components_at(detail::to_point(p)).empty();
  }
  bool motion_is_free(const ExactPoint& a, const ExactPoint& b) override {
    return motion_is_free_between(a, b, nullptr, nullptr);
  }
  bool keeps_free_regions() const override { return true; }
  std::shared_ptr<const FreeRegion> free_region(const ExactPoint& p) override {
    auto region = std::make_shared<PolygonFreeRegion>();
    region->point = detail::to_point(p);
    bool free = false;
    if (triangulation_.in_frame(p)) region->place = triangulation_.place(region->point, free);
    else free = is_free(p);
    return free ? region : nullptr;
  }
  bool motion_is_free_between(const ExactPoint& a, const ExactPoint& b, const FreeRegion* a_region,
                              const FreeRegion* b_region) override {
    const PolygonFreeRegion *from = polygon_region(a_region), *to = polygon_region(b_region);
    const bool beyond_frame = from ? !from->place : !triangulation_.in_frame(a);
    if (beyond_frame || (to ? !to->place : !triangulation_.in_frame(b))) return check_segment(*cspace_, a, b).valid;
    return !triangulation_.why_blocked(from ? from->point : detail::to_point(a), to ? to->point : detail::to_point(b),
                                       from ? from->place.get() : nullptr);
  }
  std::optional<std::string> query_not_free(const Query& query) override {
    if (box_.empty()) return "the robot does not fit in the bounds";
    return cspace_->query_not_free(query);
  }
  ExactPoint start(const Query& query) const override { return query.start; }
  ExactPoint goal(const Query& query) const override { return query.goal; }
  std::string certificate_method() const override {
    return "exact segment test (triangulation walk), the whole path checked exactly";
  }
  std::optional<std::string> why_path_invalid(const std::vector<ExactPoint>& path) override {
    const PathCheck check = check_path(*cspace_, path);
    return check.valid ? std::nullopt : std::optional<std::string>(check.reason);
  }

 private:
  const CSpace* cspace_;
  Box box_;
  detail::FreeSpaceTriangulation triangulation_;
};

}  // namespace

std::unique_ptr<SamplingSpace<TranslatingRobot>> polygon_sampling_space(const CSpace& cspace) {
  return std::make_unique<PolygonSamplingSpace>(cspace);
}

}  // namespace polyplan
