#pragma once
// Small car worlds written in the tests, for the car folder's tests.
#include <polyplan/geometry/world.hpp>
#include <polyplan/io/world_reader.hpp>

#include <string>

namespace polyplan::test {

// A world read from JSON text (the reader's checks included).
inline World car_world(const std::string& json) { return parse_world(json, "car test world"); }

}  // namespace polyplan::test
