#pragma once
// A map as Python gives it: a MovingAI .map file's path, or an occupancy grid — a numpy array (or
// nested lists) indexed [row, column], True or 1 where blocked, row = y and column = x as in
// MovingAI maps — for polyplan.replan and polyplan.scen.
#include <polyplan/io/movingai_map.hpp>

#include <pybind11/pybind11.h>

#include <string>

namespace polyplan::python {

// InputError beginning with `what` for a grid that is not 2-d, empty, not booleans or 0/1
// integers (naming its dtype and shape, or the cell), or larger than the maps polyplan reads.
GridMap grid_map_of(const pybind11::object& map, const std::string& what);

}  // namespace polyplan::python
