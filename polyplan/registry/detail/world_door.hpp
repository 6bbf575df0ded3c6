#pragma once
// What the doors of polygon worlds share (problem/translating_space.cpp, rotating_space.cpp,
// car_space.cpp): the world's own queries, its checks, a caller's query read as (x, y) or
// (x, y, θ) with θ in degrees. Not installed.
#include <polyplan/geometry/world.hpp>
#include <polyplan/registry/detail/space_door.hpp>
#include <polyplan/registry/world_queries.hpp>

namespace polyplan::detail {

// A caller's query with each orientation it gave (none for (x, y)), checked as the world reader
// checks a query's.
Query world_query(const QuerySpec& spec);

template <class Space>
class WorldDoor : public SpaceDoor<Space> {
 public:
  std::string_view kind() const override { return "World"; }
  std::string_view file() const override { return "WORLD.json"; }
  Query own_query(const Problem& problem, std::size_t index) const override {
    return problem.world()->queries.at(index);
  }
  void require_fits(const Problem& problem, std::string_view planner) const override {
    require_planner_for_robot(*problem.world(), planner);
  }
  void require_plannable(const Problem& problem, std::string_view planner) const override {
    require_plannable_queries(*problem.world(), nullptr, planner);
  }
  std::size_t columns(const Problem&) const override { return 3; }  // x, y, θ
};

}  // namespace polyplan::detail
