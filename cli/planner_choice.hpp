#pragma once
// How a command picks a planner of one or more configuration spaces (`polyplan plan` answers
// translating and rotating robots) and sets its options, for every planner of the spaces'
// registries alike: `--planner NAME` (and the aliases older scripts use), `--option NAME=VALUE`
// (repeatable), and `--NAME VALUE` for every option name some planner has (`--NAME` /
// `--no-NAME` for true-or-false options). The flags come from the registries, so a new planner's
// options reach the command line without code here.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>

#include <CLI/CLI.hpp>

#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan::cli {

template <class... Spaces>
class PlannerChoice {
 public:
  // `flag` is the primary flag ("--planner", "--method"); `aliases` name it too ("--roadmap").
  // `reserved` are the command's own flags, which no option may shadow.
  PlannerChoice(CLI::App& command, const std::string& flag, const std::vector<std::string>& aliases,
                std::string default_planner, const std::set<std::string>& reserved)
      : flag_(flag), name_(std::move(default_planner)) {
    std::string flags = flag;
    for (const auto& a : aliases) flags += "," + a;
    chosen_ = command.add_option(flags, name_, "planner: " + names() + " (polyplan planners lists them)");
    chosen_->capture_default_str();
    command.add_option("--option", assignments_, "set a planner option: NAME=VALUE (repeatable)")->allow_extra_args(false);

    // One typed flag per option name, whichever planners have it.
    std::map<std::string, std::pair<OptionInfo, std::vector<std::string>>> options;  // name → info, planners
    std::set<std::string> planner_names;
    const auto collect = [&](const auto& registry) {
      for (const auto& entry : registry.entries()) {
        // One planner in several spaces (rrt for polygons and cars) is one source: its options once.
        if (!planner_names.insert(entry.name).second) continue;
        for (const OptionInfo& option : entry.options) {
          auto& [info, owners] = options[option.name];
          if (owners.empty()) info = option;
          else if (info.flag != option.flag)
            throw std::logic_error("the option " + option.name + " is a flag for some planners and takes a value for others");
          owners.push_back(entry.name);
        }
      }
    };
    (collect(planners<Spaces>()), ...);
    for (const auto& [name, described] : options) {
      const auto& [info, owners] = described;
      if (reserved.count("--" + name)) throw std::logic_error("the planner option " + name + " shadows a command flag");
      std::string help = info.description + " [" + info.kind + "] (";
      for (std::size_t i = 0; i < owners.size(); ++i) help += (i ? ", " : "") + owners[i];
      help += ")";
      auto value = std::make_shared<std::string>();
      CLI::Option* option = info.flag ? command.add_flag("--" + name + "{true},--no-" + name + "{false}", *value, help)
                                      : command.add_option("--" + name, *value, help);
      typed_.push_back({name, value, option});
    }
  }

  // Another spelling of one option's value (`--eager` for evaluation=eager): a flag that sets it.
  CLI::Option* add_alias(CLI::App& command, const std::string& alias, const std::string& option, const std::string& value,
                         const std::string& help) {
    auto given = std::make_shared<bool>(false);
    CLI::Option* flag = command.add_flag(alias, *given, help);
    aliases_.push_back({option, value, given, alias});
    return flag;
  }

  // Unless the command line names a planner, `name` instead of the default (a car world's own
  // default planner).
  void default_to(std::string name) {
    if (chosen_->count() == 0) name_ = std::move(name);
  }

  // The space the problem is in (a car world's: SteeredCar): a name registered for several
  // spaces (rrt) plans there when it is registered there.
  template <class Space>
  void prefer() {
    preferred_ = &space_tag<Space>;
    preferred_has_ = [](const std::string& name) { return planners<Space>().find(name) != nullptr; };
  }
  // Whether the chosen planner plans in `Space`: registered there, and not in the preferred
  // space instead.
  template <class Space>
  bool chose() const {
    if (preferred_ && preferred_ != &space_tag<Space> && preferred_has_(name_)) return false;
    return planners<Space>().find(name_) != nullptr;
  }

  // The chosen planner's name and options; InputError for a name nobody registered.
  const std::string& name() const {
    chosen_options();
    return name_;
  }

  // Every option given, checked against the chosen planner: InputError naming the flag for one
  // it does not have, or for one given twice.
  OptionValues values() const {
    const std::vector<OptionInfo>& options = chosen_options();
    OptionValues values;
    std::set<std::string> given;
    const auto add = [&](const std::string& name, const std::string& value, const std::string& as) {
      bool known = false;
      for (const OptionInfo& o : options) known |= o.name == name;
      if (!known) throw InputError(as + ": the planner " + name_ + " has no option " + name + " (" + option_names(options) + ")");
      if (!given.insert(name).second) throw InputError(as + ": the option " + name + " is given twice");
      values.emplace_back(name, value);
    };
    for (const std::string& assignment : assignments_) {
      const auto equals = assignment.find('=');
      if (equals == std::string::npos || equals == 0)
        throw InputError("--option " + assignment + ": expected NAME=VALUE");
      add(assignment.substr(0, equals), assignment.substr(equals + 1), "--option " + assignment);
    }
    for (const Typed& t : typed_)
      if (t.option->count() > 0) add(t.name, *t.value, "--" + t.name);
    for (const Alias& a : aliases_)
      if (*a.given) add(a.option, a.value, a.flag);
    return values;
  }

  // The planner built for `problem` with the options given; the chosen planner must plan in
  // `Space` (chose<Space>()).
  template <class Space>
  std::unique_ptr<Planner<Space>> make(const typename Space::Problem& problem) const {
    const PlannerEntry<Space>* entry = planners<Space>().find(name());
    if (!entry) throw std::logic_error("the planner " + name_ + " does not plan in this space");
    return entry->make(problem, values());
  }

 private:
  template <class Space>
  static constexpr char space_tag = 0;  // its address names the space

  // Every space's planners, each name once.
  static std::string names() {
    std::string all;
    std::set<std::string> named;
    const auto add = [&](const auto& registry) {
      for (const auto& entry : registry.entries())
        if (named.insert(entry.name).second) all += (all.empty() ? "" : ", ") + entry.name;
    };
    (add(planners<Spaces>()), ...);
    return all;
  }

  const std::vector<OptionInfo>& chosen_options() const {
    const std::vector<OptionInfo>* options = nullptr;
    const auto look = [&](const auto& registry) {
      if (const auto* entry = registry.find(name_); entry && !options) options = &entry->options;
    };
    (look(planners<Spaces>()), ...);
    if (!options) throw InputError(flag_ + ": unknown planner \"" + name_ + "\" (" + names() + ")");
    return *options;
  }

  static std::string option_names(const std::vector<OptionInfo>& options) {
    if (options.empty()) return "it takes none";
    std::string names = "its options:";
    for (const OptionInfo& o : options) names += " " + o.name;
    return names;
  }

  struct Typed {
    std::string name;
    std::shared_ptr<std::string> value;
    CLI::Option* option;
  };
  struct Alias {
    std::string option, value;
    std::shared_ptr<bool> given;
    std::string flag;
  };

  std::string flag_;
  std::string name_;
  const char* preferred_ = nullptr;
  bool (*preferred_has_)(const std::string&) = nullptr;
  CLI::Option* chosen_ = nullptr;
  std::vector<std::string> assignments_;
  std::vector<Typed> typed_;
  std::vector<Alias> aliases_;
};

}  // namespace polyplan::cli
