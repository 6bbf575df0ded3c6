#pragma once
// Whether two configurations lie in one connected component of the free space (CSpace::locate:
// a point in contact belongs to the components it touches, a blocked one to none). When they do
// not, no path joins them: a proof any planner may answer no_path with.
#include <polyplan/geometry/cspace.hpp>

namespace polyplan {

bool share_a_component(const CSpace& cspace, const ExactPoint& a, const ExactPoint& b);

}  // namespace polyplan
