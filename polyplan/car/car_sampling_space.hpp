#pragma once
// The steered car as a sampling space (sampling/sampling_space.hpp), so that prm, lazyprm, rrt,
// rrtstar and rrtconnect plan for it: poses (x, y, heading) drawn from the bounds, joined by the
// car's shortest curve (Reeds–Shepp when it may reverse, Dubins otherwise), whose length is the
// distance — a car that cannot reverse finds b farther from a than a from b — and every segment
// of a curve certified (car/car_collision.hpp). The nearest-neighbour index holds the positions:
// the distance between them bounds any curve's length from below, either way, so the index's
// answers, refined by the curves' lengths, are the true nearest. The path is reported cut at its
// segments' joints, with its gear changes.
#include <polyplan/sampling/sampling_space.hpp>

#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/planner.hpp>

#include <memory>

namespace polyplan {

// The world (which must outlive the space) must have a car: std::invalid_argument otherwise.
std::unique_ptr<SamplingSpace<SteeredCar>> car_sampling_space(const World& world);

}  // namespace polyplan
