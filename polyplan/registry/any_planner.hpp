#pragma once
// The front door (docs/architecture.md): make_planner(name, problem, options) builds the planner
// of the registry that plans for this problem, settling once which configuration space that is;
// its plan(...) answers a Report. The command line, Python and experiments go through here and
// name no space, planner or default of their own.
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/query_spec.hpp>
#include <polyplan/registry/report.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

// One planner of the registry as listings show it.
struct PlannerListing {
  std::string name;
  std::string space;  // what it plans for: "a polygon robot translating in a polygon world", ...
  std::string kind;   // the kind of problem, as messages name it: "World", "Arm"
  std::string file;   // how usage lines name such a problem's file: "WORLD.json", "CAR_WORLD.json", "ARM.json"
  std::string description;
  std::vector<OptionInfo> options;
  bool anytime = false;                // improves its solution until its limit (RRT*)
  bool follows_world_changes = false;  // plans a world whose obstacles change as the robot drives
  bool plans_round_worlds = false;     // plans with discs, walls, disc bounds and a disc robot
};

class AnyPlanner {
 public:
  virtual ~AnyPlanner() = default;

  const PlannerListing& listing() const { return listing_; }
  const std::string& name() const { return listing_.name; }
  const Problem& problem() const { return problem_; }

  // InputError unless every query of the problem's own is one this planner can be asked (the
  // problem has a query; every start and goal is free, for this planner's robot), as `polyplan
  // plan` checks them before planning. A query asked alone needs none of this: a start that is
  // not free is an answer there (status invalid_query).
  virtual void require_plannable() const = 0;
  // The problem's own query number `query` (query_names() order).
  virtual Report plan(std::size_t query, const QueryOptions& options = {}) = 0;
  // A query of the caller's: InputError when it does not fit the problem (a pose for a robot
  // that only translates, three joint angles for a two-link arm, ...).
  virtual Report plan(const QuerySpec& query, const QueryOptions& options = {}) = 0;

 protected:
  AnyPlanner(PlannerListing listing, Problem problem) : listing_(std::move(listing)), problem_(std::move(problem)) {}

 private:
  PlannerListing listing_;
  Problem problem_;
};

// The planner `name` for `problem` with `options` (NAME=VALUE as the command line gives them).
// InputError naming the planner when nobody registered it, when it plans for another kind of
// problem (saying which, and which planners plan this one), or when an option is unknown or out
// of its range.
std::unique_ptr<AnyPlanner> make_planner(std::string_view name, const Problem& problem,
                                         const OptionValues& options = {});

// What `name` is for this problem: its listing in the space that plans it, or InputError as
// make_planner's (before anything is built).
const PlannerListing& planner_for(std::string_view name, const Problem& problem);

// The planner a problem gets when none is named: the registry's default for its space (a world
// that changes: the first that follows changes; a world whose queries turn the robot: the
// rotation space's).
std::string default_planner(const Problem& problem);

// Every planner of every space, in the registries' order (a name registered for several spaces
// is listed once per space).
const std::vector<PlannerListing>& planner_catalog();

// Each listing's name once, for messages: "visibility, visibility-full, raster, ...".
std::string planner_names(const std::vector<PlannerListing>& listings);

// The planner families this build leaves out (cmake -DPOLYPLAN_FAMILIES), for messages: "" when
// it has every one, else "grids, incremental, ...".
std::string families_left_out();

}  // namespace polyplan
