#pragma once
// A query's start and goal among discs and walls, as RoundWorld::config_not_free decides each:
// what every planner of a round world (RoundRobot) asks before it plans.
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/geometry/world.hpp>

#include <optional>
#include <string>
#include <utility>

namespace polyplan {

// "start (1, 2) is not free: it overlaps discs[0]" for the first of start and goal that is not
// free, or none.
inline std::optional<std::string> query_not_free(const RoundWorld& world, const Query& query) {
  for (const auto& [what, p] : {std::pair{"start ", &query.start}, std::pair{"goal ", &query.goal}})
    if (auto why = world.config_not_free(*p)) return what + *why;
  return std::nullopt;
}

}  // namespace polyplan
