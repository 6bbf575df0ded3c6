#pragma once
// The planners of planar arms (`polyplan arm --method NAME`), in the registry of roadmaps/registry.hpp.
#include <polyplan/roadmaps/registry.hpp>

namespace polyplan {

template <>
const PlannerRegistry<PlanarArm>& planners<PlanarArm>();

}  // namespace polyplan
