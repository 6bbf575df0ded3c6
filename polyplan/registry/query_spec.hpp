#pragma once
// A query a caller asks in the problem file's own terms (Python's plan(start=..., goal=...)):
// its numbers exact, as a file would write them. Each kind of problem reads it as its file reader
// reads a query, with the same checks (registry/any_planner.hpp).
#include <polyplan/geometry/rational.hpp>

#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct QuerySpec {
  std::string name = "start/goal";
  // A world's (x, y), or (x, y, θ) with θ in degrees (a turning robot's or a car's pose); an
  // arm's joint angles in radians.
  std::vector<Rational> start, goal;
  // An arm's hand at (x, y) instead of `goal`, and with goal_orientation the last link's
  // absolute angle there (radians): the planners plan to the free inverse-kinematics solutions.
  std::vector<Rational> goal_point;
  std::optional<Rational> goal_orientation;
};

}  // namespace polyplan
