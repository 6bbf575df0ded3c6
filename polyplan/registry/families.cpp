// Which planner families this build holds: cmake/families.cmake defines POLYPLAN_WITH_NAME for
// the registry, and this is where the programs above it ask.
#include <polyplan/registry/any_planner.hpp>

#include <string_view>
#include <utility>

namespace polyplan {

std::string families_left_out() {
  constexpr std::pair<std::string_view, bool> families[] = {
      {"grids", POLYPLAN_WITH_GRIDS},       {"incremental", POLYPLAN_WITH_INCREMENTAL},
      {"reactive", POLYPLAN_WITH_REACTIVE}, {"homotopy", POLYPLAN_WITH_HOMOTOPY},
      {"rotation", POLYPLAN_WITH_ROTATION}, {"sampling", POLYPLAN_WITH_SAMPLING},
      {"arm", POLYPLAN_WITH_ARM},           {"car", POLYPLAN_WITH_CAR},
  };
  std::string names;
  for (const auto& [name, built] : families)
    if (!built) names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

}  // namespace polyplan
