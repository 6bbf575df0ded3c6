#include <polyplan/registry/any_planner.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/detail/space_door.hpp>
#include <polyplan/registry/registry.hpp>

#include <set>
#include <type_traits>

namespace polyplan {
namespace {

using detail::space_door;

template <class Space>
PlannerListing listing_of(const PlannerEntry<Space>& entry) {
  const auto& door = space_door<Space>();
  return {entry.name,
          std::string(Space::description),
          std::string(door.kind()),
          std::string(door.file()),
          entry.description,
          entry.options,
          entry.anytime,
          entry.follows_world_changes,
          entry.plans_round_worlds};
}

// A registry planner of one space, built for a problem that space plans.
template <class Space>
class PlannerIn final : public AnyPlanner {
 public:
  PlannerIn(const PlannerEntry<Space>& entry, const Problem& problem, const OptionValues& options)
      : AnyPlanner(listing_of(entry), problem), door_(space_door<Space>()),
        planner_(entry.make(door_.built_from(this->problem()), options)) {}

  void require_plannable() const override { door_.require_plannable(problem(), name()); }

  Report plan(std::size_t query, const QueryOptions& options) override {
    return answer(door_.own_query(problem(), query), options);
  }
  Report plan(const QuerySpec& query, const QueryOptions& options) override {
    return answer(door_.query(problem(), query), options);
  }

 private:
  Report answer(const typename Space::Query& query, const QueryOptions& options) {
    Report report(planner_->plan(query, options), door_, door_.columns(problem()), query.name, name());
    if constexpr (requires { query.goal_point; }) report.target = query.goal_point;
    return report;
  }

  const detail::SpaceDoor<Space>& door_;
  std::unique_ptr<Planner<Space>> planner_;
};

// `name`'s entry in the first space that plans `problem` and registered it, with `found` called
// on it; false when there is none.
template <class Found>
bool find_entry(std::string_view name, const Problem& problem, Found found) {
  return detail::any_space([&](auto tag) {
    using Space = typename decltype(tag)::Space;
    if (!space_door<Space>().plans(problem)) return false;
    const PlannerEntry<Space>* entry = planners<Space>().find(name);
    if (!entry) return false;
    space_door<Space>().require_fits(problem, name);
    found(*entry);
    return true;
  });
}

// "a World", "an Arm".
std::string with_article(std::string_view word) {
  return (std::string_view("AEIOU").find(word.front()) != std::string_view::npos ? "an " : "a ") + std::string(word);
}

// The door of the space a listed planner plans in.
const detail::SpaceWords& door_of(const PlannerListing& listing) {
  const detail::SpaceWords* door = nullptr;
  detail::any_space([&](auto tag) {
    door = &space_door<typename decltype(tag)::Space>();
    return listing.space == door->description();
  });
  return *door;
}

// Why nothing plans `problem` by `name`: nobody registered it, or its spaces plan other problems.
[[noreturn]] void refuse(std::string_view name, const Problem& problem) {
  std::vector<PlannerListing> here;
  const PlannerListing* registered = nullptr;
  std::string_view kind;  // the problem's
  for (const PlannerListing& listing : planner_catalog()) {
    if (listing.name == name && !registered) registered = &listing;
    if (!door_of(listing).plans(problem)) continue;
    here.push_back(listing);
    kind = door_of(listing).kind();
  }
  if (!registered) {
    const std::string left_out = families_left_out();
    throw InputError("unknown planner \"" + std::string(name) + "\" (" + planner_names(planner_catalog()) + ")" +
                     (left_out.empty() ? ""
                                       : "; this polyplan is built without the " + left_out +
                                             " planners (cmake -DPOLYPLAN_FAMILIES=all)"));
  }
  // A space's own words first: a car planner for a robot that does not steer, and the reverse.
  detail::any_space([&](auto tag) {
    const auto& door = space_door<typename decltype(tag)::Space>();
    if (door.plans(problem)) door.require_fits(problem, name);
    return false;
  });
  throw InputError("planner " + std::string(name) + " plans in " + with_article(registered->kind) + " (" +
                   registered->space + "), not in " + with_article(kind) + " (" + problem.source() +
                   "; its planners: " + planner_names(here) + ")");
}

}  // namespace

std::unique_ptr<AnyPlanner> make_planner(std::string_view name, const Problem& problem, const OptionValues& options) {
  std::unique_ptr<AnyPlanner> built;
  const bool found = find_entry(name, problem, [&](const auto& entry) {
    using Space = typename std::decay_t<decltype(entry)>::SpaceType;
    built = std::make_unique<PlannerIn<Space>>(entry, problem, options);
  });
  if (!found) refuse(name, problem);
  return built;
}

const PlannerListing& planner_for(std::string_view name, const Problem& problem) {
  for (const PlannerListing& listing : planner_catalog())
    if (listing.name == name && door_of(listing).plans(problem)) {
      door_of(listing).require_fits(problem, name);
      return listing;
    }
  refuse(name, problem);
}

std::string default_planner(const Problem& problem) {
  std::string name;
  detail::any_space([&](auto tag) {
    using Space = typename decltype(tag)::Space;
    if (!space_door<Space>().plans(problem)) return false;
    name = space_door<Space>().default_planner(problem);
    return true;
  });
  return name;
}

const std::vector<PlannerListing>& planner_catalog() {
  static const std::vector<PlannerListing> catalog = [] {
    std::vector<PlannerListing> all;
    detail::any_space([&](auto tag) {
      for (const auto& entry : planners<typename decltype(tag)::Space>().entries()) all.push_back(listing_of(entry));
      return false;
    });
    return all;
  }();
  return catalog;
}

std::string planner_names(const std::vector<PlannerListing>& listings) {
  std::string names;
  std::set<std::string> named;
  for (const PlannerListing& listing : listings)
    if (named.insert(listing.name).second) names += (names.empty() ? "" : ", ") + listing.name;
  return names;
}

}  // namespace polyplan
