#include <polyplan/sampling/round_sampling_space.hpp>

#include <polyplan/geometry/rational.hpp>
#include <polyplan/sampling/detail/sampling_box.hpp>

#include <array>
#include <cmath>

namespace polyplan {
namespace {

using Box = detail::SamplingBox;

// Everything the world holds, grown for a world without bounds.
Box unbounded_box(const World& world) {
  Box box;
  for (const PolygonWithHoles& p : world.obstacles)
    for (const ExactPoint& v : p.outer) box.add(v);
  for (const Disc& d : world.discs) {
    const double r = to_double(d.radius);
    box.add(to_double(d.center.x) - r, to_double(d.center.y) - r);
    box.add(to_double(d.center.x) + r, to_double(d.center.y) + r);
  }
  for (const Wall& wall : world.walls)
    for (const ExactPoint& v : wall) box.add(v);
  for (const Query& q : world.queries) box.add(q.start), box.add(q.goal);
  box.grow_for_unbounded();
  return box;
}

class RoundSamplingSpace final : public SamplingSpace<RoundRobot> {
 public:
  explicit RoundSamplingSpace(const RoundWorld& world) : world_(&world) {
    if (const auto& disc = world.reference_disc()) {
      centre_ = {to_double(disc->center.x), to_double(disc->center.y)};
      radius_ = to_double(disc->radius);
      if (radius_ > 0)
        box_.add(centre_[0] - radius_, centre_[1] - radius_), box_.add(centre_[0] + radius_, centre_[1] + radius_);
    } else if (const auto& b = world.reference_box()) {
      if (b->xmin <= b->xmax && b->ymin <= b->ymax) box_.add({b->xmin, b->ymin}), box_.add({b->xmax, b->ymax});
    } else {
      box_ = unbounded_box(world.world());
    }
  }

  std::size_t dimension() const override { return 2; }
  SamplingMetric metric() const override { return SamplingMetric::euclidean; }
  double extent() const override { return box_.empty() ? 0 : std::hypot(box_.xmax - box_.xmin, box_.ymax - box_.ymin); }
  double volume() const override {
    if (box_.empty()) return 0;
    return radius_ > 0 ? std::acos(-1.0) * radius_ * radius_ : (box_.xmax - box_.xmin) * (box_.ymax - box_.ymin);
  }

  // Uniform in the box, or in the disc by drawing from its box until a point falls inside (π/4 of
  // the draws do): the same numbers of the seed on every machine.
  void sample(SamplingRandom& random, std::span<double> out) const override {
    do {
      out[0] = box_.xmin + uniform01(random) * (box_.xmax - box_.xmin);
      out[1] = box_.ymin + uniform01(random) * (box_.ymax - box_.ymin);
    } while (radius_ > 0 && std::hypot(out[0] - centre_[0], out[1] - centre_[1]) > radius_);
  }
  std::optional<std::string> outside(std::span<const double> c) const override { return box_.outside(c); }
  void coordinates(const ExactPoint& p, std::span<double> out) const override {
    out[0] = to_double(p.x);
    out[1] = to_double(p.y);
  }
  ExactPoint configuration(std::span<const double> c) const override { return {Rational(c[0]), Rational(c[1])}; }

  bool is_free(const ExactPoint& p) override { return !world_->config_not_free(p); }
  bool motion_is_free(const ExactPoint& a, const ExactPoint& b) override { return world_->check_segment(a, b).valid; }
  std::optional<std::string> query_not_free(const Query& query) override {
    if (box_.empty()) return "the robot does not fit in the bounds";
    for (const auto& [what, p] : {std::pair{"start", &query.start}, std::pair{"goal", &query.goal}})
      if (auto why = world_->config_not_free(*p)) return std::string(what) + " " + *why;
    return std::nullopt;
  }
  ExactPoint start(const Query& query) const override { return query.start; }
  ExactPoint goal(const Query& query) const override { return query.goal; }
  std::string certificate_method() const override {
    return "exact rational segment tests among discs, walls and polygons, the whole path checked exactly";
  }
  std::optional<std::string> why_path_invalid(const std::vector<ExactPoint>& path) override {
    const PathCheck check = world_->check_path(path);
    return check.valid ? std::nullopt : std::optional<std::string>(check.reason);
  }

 private:
  const RoundWorld* world_;
  Box box_;
  std::array<double, 2> centre_{0, 0};
  double radius_ = 0;  // > 0: samples in the disc of this radius round centre_
};

}  // namespace

std::unique_ptr<SamplingSpace<RoundRobot>> round_sampling_space(const RoundWorld& world) {
  return std::make_unique<RoundSamplingSpace>(world);
}

}  // namespace polyplan
