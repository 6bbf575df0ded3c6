#pragma once
// What the front door knows of each configuration space (plan/planner.hpp): which problems it
// plans, what its planners are built from, how a caller's query and a problem's own queries
// become its Query, and the words its listings and summary lines use. One door per space, each in its own file
// (registry/NAME_space.cpp); `Spaces` lists them. A new kind of problem is its family, its list in
// registry/, and here one file, one declaration and one entry of `Spaces`. Not installed.
#include <polyplan/plan/planner.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/query_spec.hpp>
#include <polyplan/registry/report.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan::detail {

// What a door says of its space whatever the space's types: for listings, messages and the
// summary line of a report (Report keeps its space's words).
class SpaceWords {
 public:
  virtual ~SpaceWords() = default;
  // The space's description (Space::description).
  virtual std::string_view description() const = 0;
  // The kind of problem its planners plan, as messages name it: "World", "Arm".
  virtual std::string_view kind() const = 0;
  // How usage lines name the file of such a problem: "WORLD.json", "ARM.json".
  virtual std::string_view file() const = 0;
  // Whether a planner of this space's registry plans `problem` (a car's world: the car's space).
  virtual bool plans(const Problem& problem) const = 0;
  // InputError when `planner`, registered for this space, cannot plan this problem all the same
  // (a world that changes, for a planner of a world that stands still).
  virtual void require_fits(const Problem&, std::string_view /*planner*/) const {}
  // The summary line's words: what a path's steps are ("segment"), the unit of its length (" rad").
  virtual std::string_view steps() const { return "segment"; }
  virtual std::string_view unit() const { return ""; }
  // What the summary line adds for this space after the shared facts (", 2 gear change(s)").
  virtual std::string summary(const Facts&) const { return ""; }
};

template <class Space>
class SpaceDoor : public SpaceWords {
 public:
  std::string_view description() const final { return Space::description; }
  // What the space's planners are built from (a world's C-space, the world, an arm problem).
  virtual const typename Space::Problem& built_from(const Problem& problem) const = 0;
  virtual typename Space::Query own_query(const Problem& problem, std::size_t index) const = 0;
  // InputError naming the field when the caller's query does not fit the problem.
  virtual typename Space::Query query(const Problem& problem, const QuerySpec& spec) const = 0;
  // InputError unless every query of the problem's own can be asked of `planner`.
  virtual void require_plannable(const Problem& problem, std::string_view planner) const = 0;
  // The planner a problem of this space gets when none is named.
  virtual std::string default_planner(const Problem& problem) const = 0;
  // The numbers of one configuration (Report::path_columns).
  virtual std::size_t columns(const Problem& problem) const = 0;
};

// Each space's door, defined in its file.
template <class Space>
const SpaceDoor<Space>& space_door();
template <>
const SpaceDoor<TranslatingRobot>& space_door<TranslatingRobot>();
template <>
const SpaceDoor<RotatingRobot>& space_door<RotatingRobot>();
template <>
const SpaceDoor<SteeredCar>& space_door<SteeredCar>();
template <>
const SpaceDoor<PlanarArm>& space_door<PlanarArm>();
template <>
const SpaceDoor<RoundRobot>& space_door<RoundRobot>();

template <class... S>
struct SpaceList {};
// Every space, in the order listings show them and a planner's name is looked up (a world's
// translating planners before its rotating ones). A car's world is planned by the car's space
// alone, so rrt, registered for both, plans the car there; a world with discs or walls and a point
// or disc robot by the round robot's space alone (the translating robot's door leaves it out).
using Spaces = SpaceList<TranslatingRobot, RotatingRobot, SteeredCar, PlanarArm, RoundRobot>;

template <class S>
struct SpaceTag {
  using Space = S;
};
// f(SpaceTag<S>{}) for each space in order until one returns true; whether one did.
template <class F, class... S>
bool any_space(SpaceList<S...>, F&& f) {
  return (f(SpaceTag<S>{}) || ...);
}
template <class F>
bool any_space(F&& f) {
  return any_space(Spaces{}, std::forward<F>(f));
}

}  // namespace polyplan::detail
