#pragma once
// The sampling planners' space for a point or disc robot among discs, walls and polygons
// (sampling/sampling_space.hpp, RoundRobot): configurations are the robot's exact centres; samples
// are uniform in the box or disc where the centre may be (the bounds less the robot's radius), or,
// in a world without bounds, in the box of everything grown by a tenth of its diagonal on every
// side; a position is free unless nearer an obstacle than the robot's radius (contact is free); a
// motion is the straight segment, decided exactly in rationals (geometry/round_world_check.hpp:
// grazing allowed, no crossing a wall, no passing where obstacles touch).
#include <polyplan/plan/planner.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <memory>

namespace polyplan {

// The space of `world`, which must outlive it.
std::unique_ptr<SamplingSpace<RoundRobot>> round_sampling_space(const RoundWorld& world);

}  // namespace polyplan
