#pragma once
// A world without bounds is framed: its free space is triangulated, decomposed or diagrammed
// inside a box around its obstacles and its queries (geometry/detail/free_space_frame.hpp). A
// planner built over such a frame and asked about a point beyond it builds anew, around that
// query too.
#include <polyplan/geometry/world.hpp>

#include <optional>
#include <vector>

namespace polyplan {

// nullopt when `framed` (anything with in_frame(ExactPoint)) holds the query's start and goal;
// otherwise the points a new frame must hold: the world's queries' and this one's.
template <class Framed>
std::optional<std::vector<ExactPoint>> points_to_reframe(const Framed& framed, const World& world, const Query& query) {
  if (framed.in_frame(query.start) && framed.in_frame(query.goal)) return std::nullopt;
  return query_points(world, {query.start, query.goal});
}

}  // namespace polyplan
