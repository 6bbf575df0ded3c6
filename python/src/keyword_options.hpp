#pragma once
// Python's keyword arguments as the options a table of options reads (plan/planner_options.hpp):
// goal_bias=0.2 is the option goal-bias with the text "0.2". One conversion for planners and for
// the commands' own option tables (replan), so that both take the same values the same way.
#include <polyplan/plan/planner_options.hpp>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace polyplan::python {

// `owner` names whose options they are in messages ("planner rrt", "replan"): InputError naming the
// argument as the caller spelt it when there is no such option, or for a value that is not a number,
// text, True or False (or, for a point option, a pair of numbers).
OptionValues keyword_options(const std::string& owner, const std::vector<OptionInfo>& options,
                             const pybind11::dict& given);

}  // namespace polyplan::python
