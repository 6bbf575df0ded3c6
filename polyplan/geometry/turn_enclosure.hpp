#pragma once
// What a robot sweeps while it turns on the spot, enclosed in polygons: the "turn layer" of a
// rotating robot. A position from which the enclosure is free (in the exact C-space of a robot made
// of the enclosure's polygons) is a position where the turn is free for every intermediate angle,
// proved, not sampled.
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/world.hpp>

namespace polyplan {

// Convex polygons (counter-clockwise, exact) that together contain every point of `robot` turned
// about its reference point by any angle between `from` and `to`, the short way (less than 180
// degrees). Each part is first split into convex pieces; each piece gives one polygon, the convex
// hull of its vertices at both rotations and of the tangent apexes of their arcs (the proof is in
// turn_enclosure.cpp). from == to gives the robot at that rotation. Throws std::invalid_argument
// for a half turn (180 degrees: the short way is not defined).
Robot turn_enclosure(const Robot& robot, const Rotation& from, const Rotation& to);

// The robot's parts split into convex pieces (counter-clockwise, exact): a convex part is one
// piece. What enclosures of a moving robot are built from: the sweep of a convex piece lies in the
// hull of its vertices' sweeps.
std::vector<Ring> convex_pieces(const Robot& robot);

}  // namespace polyplan
