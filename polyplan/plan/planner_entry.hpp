#pragma once
// What a planner gives the registry: its name, a one-line description, its options with their
// defaults, and a factory. Each planner's header declares one function returning its entry
// (visibility_planner_entry(), prm_planner_entry<Space>(...)); the lists of registry/ call them.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {

template <class Space>
struct PlannerEntry {
  using SpaceType = Space;
  using Factory = std::function<std::unique_ptr<Planner<Space>>(const typename Space::Problem&, const OptionValues&)>;

  std::string name;         // on the command line: --planner NAME
  std::string description;  // one line
  std::vector<OptionInfo> options;
  // Whether it follows a world's "changes" (World::changes) as its robot drives: only such a
  // planner is given a world that changes (registry/world_queries.hpp refuses the others).
  bool follows_world_changes = false;
  // Builds the planner for a problem (which must outlive it) with the options set from `values`.
  // Throws InputError naming the planner and the option for a value it refuses.
  Factory make;
  // Whether it goes on improving its solution until its limit (RRT*): a benchmark samples its
  // cost over time (PlanReport::improvements).
  bool anytime = false;
  // Whether it plans with a world's round things and thin walls (World's discs, walls, disc
  // bounds, a disc robot: round_features): registry/world_queries.hpp refuses it such a world
  // otherwise, naming what it does not plan with.
  bool plans_round_worlds = false;
};

// An entry from a plain options struct, its table, and a factory taking the parsed options. A
// factory's std::invalid_argument (a resolution out of range, say) reaches the user as InputError
// "planner NAME: ...".
template <class Space, class Options>
PlannerEntry<Space> make_planner_entry(
    std::string name, std::string description, OptionTable<Options> table,
    std::function<std::unique_ptr<Planner<Space>>(const typename Space::Problem&, const Options&)> factory) {
  PlannerEntry<Space> entry{name, std::move(description), table.info(), false, {}, false};
  entry.make = [name, table = std::move(table), factory = std::move(factory)](const typename Space::Problem& problem,
                                                                              const OptionValues& values) {
    const Options options = table.parse(values, name);
    try {
      return factory(problem, options);
    } catch (const std::invalid_argument& e) {
      throw InputError("planner " + name + ": " + e.what());
    }
  };
  return entry;
}

}  // namespace polyplan
