#include "cli/planner_choice.hpp"

#include <polyplan/geometry/input_error.hpp>

#include <map>
#include <stdexcept>

namespace polyplan::cli {
namespace {

std::string option_names(const std::vector<OptionInfo>& options) {
  if (options.empty()) return "it takes none";
  std::string names = "its options:";
  for (const OptionInfo& o : options) names += " " + o.name;
  return names;
}

}  // namespace

PlannerChoice::PlannerChoice(CLI::App& command, const std::string& flag, const std::vector<std::string>& aliases)
    : flag_(flag) {
  std::string flags = flag;
  for (const auto& a : aliases) flags += "," + a;
  chosen_ = command.add_option(flags, name_,
                               "planner: " + planner_names(planner_catalog()) +
                                   " (polyplan planners lists them; default: the problem's)");
  command.add_option("--option", assignments_, "set a planner option: NAME=VALUE (repeatable)")
      ->allow_extra_args(false);

  // One typed flag per option name, whichever planners have it.
  std::map<std::string, std::pair<OptionInfo, std::vector<std::string>>> options;  // name → info, planners
  std::set<std::string> planner_names_seen;
  for (const PlannerListing& planner : planner_catalog()) {
    // One planner in several spaces (rrt for polygons and cars) is one source: its options once.
    if (!planner_names_seen.insert(planner.name).second) continue;
    for (const OptionInfo& option : planner.options) {
      auto& [info, owners] = options[option.name];
      if (owners.empty()) info = option;
      else if (info.flag != option.flag)
        throw std::logic_error("the option " + option.name +
                               " is a flag for some planners and takes a value for others");
      owners.push_back(planner.name);
    }
  }
  for (const auto& [name, described] : options) {
    const auto& [info, owners] = described;
    if (command.get_option_no_throw("--" + name) || command.get_option_no_throw("--no-" + name))
      throw std::logic_error("the planner option " + name + " shadows a flag of the command " + command.get_name());
    std::string help = info.description + " [" + info.kind + "] (";
    for (std::size_t i = 0; i < owners.size(); ++i) help += (i ? ", " : "") + owners[i];
    help += ")";
    flags_.add(command, info, help);
  }
}

CLI::Option* PlannerChoice::add_alias(CLI::App& command, const std::string& alias, const std::string& option,
                                      const std::string& value, const std::string& help) {
  auto given = std::make_shared<bool>(false);
  CLI::Option* flag = command.add_flag(alias, *given, help);
  aliases_.push_back({option, value, given, alias});
  return flag;
}

void PlannerChoice::choose_for(const Problem& problem) {
  if (chosen_->count() == 0) name_ = default_planner(problem);
  const PlannerListing* planner = nullptr;
  try {
    planner = &planner_for(name_, problem);
  } catch (const InputError& e) {
    // A name nobody registered is the flag's mistake; the door's other refusals name the file.
    const std::string why = e.what();
    throw InputError(why.rfind("unknown planner", 0) == 0 ? flag_ + ": " + why : why);
  }
  values_ = given(*planner);
}

OptionValues PlannerChoice::given(const PlannerListing& planner) const {
  OptionValues values;
  std::set<std::string> named;
  const auto add = [&](const std::string& name, const std::string& value, const std::string& as) {
    bool known = false;
    for (const OptionInfo& o : planner.options) known |= o.name == name;
    if (!known)
      throw InputError(as + ": the planner " + name_ + " has no option " + name + " (" + option_names(planner.options) +
                       ")");
    if (!named.insert(name).second) throw InputError(as + ": the option " + name + " is given twice");
    values.emplace_back(name, value);
  };
  for (const std::string& assignment : assignments_) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0)
      throw InputError("--option " + assignment + ": expected NAME=VALUE");
    add(assignment.substr(0, equals), assignment.substr(equals + 1), "--option " + assignment);
  }
  for (const auto& [name, value] : flags_.given()) add(name, value, "--" + name);
  for (const Alias& a : aliases_)
    if (*a.given) add(a.option, a.value, a.flag);
  return values;
}

std::string PlannerChoice::settings() const {
  std::string text;
  for (const auto& [name, value] : values_) text += " · " + name + " " + value;
  return text;
}

}  // namespace polyplan::cli
