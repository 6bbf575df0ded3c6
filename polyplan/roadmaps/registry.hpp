#pragma once
// Planners by name. Each configuration space has one registry (planners<Space>()), a list of
// entries: a name, a one-line description, the options with their defaults, and a factory. The
// command-line program, the JSON writer, the pictures and the conformance test read these lists
// and nothing planner-specific, so a new planner is its header, its source and one registration
// line in the list of its space (roadmaps/registry.cpp for TranslatingRobot, arm/arm_registry.cpp
// for PlanarArm).
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/roadmaps/planner.hpp>
#include <polyplan/roadmaps/planner_options.hpp>

#include <functional>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

template <class Space>
struct PlannerEntry {
  using Factory = std::function<std::unique_ptr<Planner<Space>>(const typename Space::Problem&, const OptionValues&)>;

  std::string name;         // on the command line: --planner NAME
  std::string description;  // one line
  std::vector<OptionInfo> options;
  // Builds the planner for a problem (which must outlive it) with the options set from `values`.
  // Throws InputError naming the planner and the option for a value it refuses.
  Factory make;
};

// An entry from a plain options struct, its table, and a factory taking the parsed options. A
// factory's std::invalid_argument (a resolution out of range, say) reaches the user as InputError
// "planner NAME: ...".
template <class Space, class Options>
PlannerEntry<Space> make_planner_entry(
    std::string name, std::string description, OptionTable<Options> table,
    std::function<std::unique_ptr<Planner<Space>>(const typename Space::Problem&, const Options&)> factory) {
  PlannerEntry<Space> entry{name, std::move(description), table.info(), {}};
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

template <class Space>
class PlannerRegistry {
 public:
  // Throws std::logic_error for two entries of one name.
  PlannerRegistry(std::initializer_list<PlannerEntry<Space>> entries) {
    for (const auto& e : entries) {
      if (find(e.name)) throw std::logic_error("two planners are registered as " + e.name);
      entries_.push_back(e);
    }
  }

  const std::vector<PlannerEntry<Space>>& entries() const { return entries_; }

  // nullptr for a name nobody registered.
  const PlannerEntry<Space>* find(std::string_view name) const {
    for (const auto& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }

  // "visibility, visibility-full, raster": for messages.
  std::string names() const {
    std::string out;
    for (const auto& e : entries_) out += (out.empty() ? "" : ", ") + e.name;
    return out;
  }

 private:
  std::vector<PlannerEntry<Space>> entries_;
};

// The planners of a configuration space. Specialised (declared next to its space's list):
// planners<TranslatingRobot>() and planners<RotatingRobot>() below, planners<PlanarArm>() in arm/arm_registry.hpp.
template <class Space>
const PlannerRegistry<Space>& planners();

template <>
const PlannerRegistry<TranslatingRobot>& planners<TranslatingRobot>();
template <>
const PlannerRegistry<RotatingRobot>& planners<RotatingRobot>();

}  // namespace polyplan
