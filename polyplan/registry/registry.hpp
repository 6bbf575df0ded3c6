#pragma once
// Planners by name. Each configuration space has one registry (planners<Space>()), a list of
// PlannerEntry (plan/planner_entry.hpp). The command-line program, the Python module, the JSON
// writer, the pictures and the conformance test read these lists and nothing planner-specific,
// so a new planner is its header, its source and one registration line in the list of its space
// (registry/polygon_planners.cpp for TranslatingRobot and RotatingRobot, registry/arm_planners.cpp
// for PlanarArm, registry/car_planners.cpp for SteeredCar). These files are the only ones that name every planner.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

template <class Space>
class PlannerRegistry {
 public:
  // `default_planner` is the one a problem of this space gets when none is named. Throws
  // std::logic_error for two entries of one name, or a default nobody registered.
  PlannerRegistry(std::string default_planner, std::initializer_list<PlannerEntry<Space>> entries)
      : default_(std::move(default_planner)) {
    for (const auto& e : entries) {
      if (find(e.name)) throw std::logic_error("two planners are registered as " + e.name);
      entries_.push_back(e);
    }
    if (!find(default_)) throw std::logic_error("the default planner " + default_ + " is not registered");
  }

  // The registry of a space whose family this build leaves out (cmake -DPOLYPLAN_FAMILIES): no
  // planners, and a default planner that is refused naming the family.
  static PlannerRegistry left_out(const std::string& family) {
    PlannerRegistry registry;
    registry.left_out_ =
        "this polyplan is built without the " + family + " planners (cmake -DPOLYPLAN_FAMILIES=" + family + " or all)";
    return registry;
  }

  // InputError when this build leaves the space's planners out.
  void require_planners() const {
    if (!left_out_.empty()) throw InputError(left_out_);
  }

  const std::string& default_planner() const {
    require_planners();
    return default_;
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
  PlannerRegistry() = default;

  std::string default_;
  std::string left_out_;  // why there are no planners
  std::vector<PlannerEntry<Space>> entries_;
};

// The planners of a configuration space, one specialisation per space.
template <class Space>
const PlannerRegistry<Space>& planners();

template <>
const PlannerRegistry<TranslatingRobot>& planners<TranslatingRobot>();
template <>
const PlannerRegistry<RotatingRobot>& planners<RotatingRobot>();
template <>
const PlannerRegistry<PlanarArm>& planners<PlanarArm>();
template <>
const PlannerRegistry<SteeredCar>& planners<SteeredCar>();
template <>
const PlannerRegistry<RoundRobot>& planners<RoundRobot>();

}  // namespace polyplan
