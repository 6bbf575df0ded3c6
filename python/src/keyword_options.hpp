#pragma once
// Python's keyword arguments as the options a table of options reads (plan/planner_options.hpp):
// goal_bias=0.2 is the option goal-bias with the text "0.2". One conversion for planners and for
// the commands' own option tables (replan), so that both take the same values the same way.
#include <polyplan/plan/planner_options.hpp>

#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>
#include <vector>

namespace polyplan::python {

// `owner` names whose options they are in messages ("planner rrt", "replan"): InputError naming the
// argument as the caller spelt it when there is no such option, or for a value that is not a number,
// text, True or False (or, for a point option, a pair of numbers).
OptionValues keyword_options(const std::string& owner, const std::vector<OptionInfo>& options,
                             const pybind11::dict& given);

// A command's own options (replan's, scen's) from keyword arguments, read by the program's table:
// its checks and its messages, "OWNER: time_limit=-1: ..." as Python spells the names.
template <class Options>
Options keyword_command_options(const OptionTable<Options>& table, const std::string& owner,
                                const pybind11::dict& given) {
  return table.parse_as(keyword_options(owner, table.info(), given), [&](std::string key, const std::string& value) {
    std::replace(key.begin(), key.end(), '-', '_');
    return owner + ": " + key + "=" + value + ": ";
  });
}

}  // namespace polyplan::python
