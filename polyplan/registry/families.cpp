// Which planner families this build leaves out: cmake/families.cmake names them for the registry
// in POLYPLAN_FAMILIES_LEFT_OUT, and this is where the programs above it ask.
#include <polyplan/registry/any_planner.hpp>

namespace polyplan {

std::string families_left_out() { return POLYPLAN_FAMILIES_LEFT_OUT; }

}  // namespace polyplan
