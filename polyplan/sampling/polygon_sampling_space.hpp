#pragma once
// The sampling planners' space for a translating robot in a polygon world
// (sampling/sampling_space.hpp): configurations are the reference point's exact positions;
// samples are uniform in the reference box (the bounds shrunk by the robot), or, in a world
// without bounds, in the box of the C-obstacles and the world's queries grown by a tenth of its
// diagonal on every side (room to go around everything). A position is free unless it is inside
// a C-obstacle (contact is free); a motion is the straight segment, decided exactly by a walk in
// the free space's constrained triangulation (the verdicts of geometry/path_check.hpp: no
// entering, no passing a pinch point).
#include <polyplan/plan/planner.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <memory>

namespace polyplan {

// The space of `cspace`, which must outlive it.
std::unique_ptr<SamplingSpace<TranslatingRobot>> polygon_sampling_space(const CSpace& cspace);

}  // namespace polyplan
