#pragma once
// A sampling space (sampling/sampling_space.hpp) whatever its configurations, for callers that hold
// coordinates: distance, interpolate, steer and the certified motion test — the very functions the
// planners call, not copies. Every coordinate list given is checked first (InputError: the wrong
// count, a NaN or infinity, beyond the sampling box) and taken as the space takes a configuration
// (an arm's angles normalised into [0, 2π)). Python's polyplan.space (python/src/space.cpp).
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace polyplan {

class AnySamplingSpace {
 public:
  virtual ~AnySamplingSpace() = default;
  virtual std::size_t dimension() const = 0;
  virtual double distance(std::span<const double> a, std::span<const double> b) const = 0;
  // The coordinates a fraction t ∈ [0, 1] of the way along the motion a → b.
  virtual std::vector<double> interpolate(std::span<const double> a, std::span<const double> b, double t) const = 0;
  // At most `step` (> 0) from a toward b along that motion; b itself when nearer.
  virtual std::vector<double> steer(std::span<const double> a, std::span<const double> b, double step) const = 0;
  // Certified free (SamplingSpace::motion_is_free): false when it collides or cannot be proved free.
  virtual bool motion_is_free(std::span<const double> a, std::span<const double> b) = 0;
  virtual bool is_free(std::span<const double> a) = 0;
};

namespace detail {

template <class Space>
class AnySamplingSpaceOf final : public AnySamplingSpace {
 public:
  explicit AnySamplingSpaceOf(std::unique_ptr<SamplingSpace<Space>> space) : space_(std::move(space)) {}

  std::size_t dimension() const override { return space_->dimension(); }
  double distance(std::span<const double> a, std::span<const double> b) const override {
    return space_->distance(taken(a, "a"), taken(b, "b"));
  }
  std::vector<double> interpolate(std::span<const double> a, std::span<const double> b, double t) const override {
    if (!(t >= 0 && t <= 1)) throw InputError("t: expected a number in [0, 1]");
    std::vector<double> out(dimension());
    space_->interpolate(taken(a, "a"), taken(b, "b"), t, out);
    return out;
  }
  std::vector<double> steer(std::span<const double> a, std::span<const double> b, double step) const override {
    if (!(step > 0) || !std::isfinite(step)) throw InputError("step: expected a distance above 0");
    std::vector<double> out(dimension());
    space_->steer(taken(a, "a"), taken(b, "b"), step, out);
    return out;
  }
  bool motion_is_free(std::span<const double> a, std::span<const double> b) override {
    return space_->motion_is_free(space_->configuration(taken(a, "a")), space_->configuration(taken(b, "b")));
  }
  bool is_free(std::span<const double> a) override { return space_->is_free(space_->configuration(taken(a, "a"))); }

 private:
  // `c` checked and as the space holds it: the coordinates of the configuration it gives.
  std::vector<double> taken(std::span<const double> c, const std::string& what) const {
    if (c.size() != dimension())
      throw InputError(what + ": expected " + std::to_string(dimension()) + " coordinates, got " +
                       std::to_string(c.size()));
    for (double x : c)
      if (!std::isfinite(x)) throw InputError(what + ": a coordinate is not a finite number");
    if (auto why = space_->outside(c)) throw InputError(what + ": " + *why);
    std::vector<double> out(dimension());
    space_->coordinates(space_->configuration(c), out);
    return out;
  }

  std::unique_ptr<SamplingSpace<Space>> space_;
};

}  // namespace detail

template <class Space>
std::unique_ptr<AnySamplingSpace> any_sampling_space(std::unique_ptr<SamplingSpace<Space>> space) {
  return std::make_unique<detail::AnySamplingSpaceOf<Space>>(std::move(space));
}

}  // namespace polyplan
