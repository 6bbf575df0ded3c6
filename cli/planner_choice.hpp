#pragma once
// How a command picks a planner of a configuration space and sets its options, for every planner
// of the space's registry alike: `--planner NAME` (and the aliases older scripts use),
// `--option NAME=VALUE` (repeatable), and `--NAME VALUE` for every option name some planner of
// the space has (`--NAME` / `--no-NAME` for true-or-false options). The flags come from the
// registry, so a new planner's options reach the command line without code here.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/roadmaps/registry.hpp>

#include <CLI/CLI.hpp>

#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan::cli {

template <class Space>
class PlannerChoice {
 public:
  // `flag` is the primary flag ("--planner", "--method"); `aliases` name it too ("--roadmap").
  // `reserved` are the command's own flags, which no option may shadow.
  PlannerChoice(CLI::App& command, const std::string& flag, const std::vector<std::string>& aliases,
                std::string default_planner, const std::set<std::string>& reserved)
      : flag_(flag), name_(std::move(default_planner)) {
    const PlannerRegistry<Space>& registry = planners<Space>();
    std::string flags = flag;
    for (const auto& a : aliases) flags += "," + a;
    command.add_option(flags, name_, "planner: " + registry.names() + " (polyplan planners lists them)")->capture_default_str();
    command.add_option("--option", assignments_, "set a planner option: NAME=VALUE (repeatable)")->allow_extra_args(false);

    // One typed flag per option name, whichever planners have it.
    std::map<std::string, std::pair<OptionInfo, std::vector<std::string>>> options;  // name → info, planners
    for (const auto& entry : registry.entries())
      for (const OptionInfo& option : entry.options) {
        auto& [info, owners] = options[option.name];
        if (owners.empty()) info = option;
        else if (info.flag != option.flag)
          throw std::logic_error("the option " + option.name + " is a flag for some planners and takes a value for others");
        owners.push_back(entry.name);
      }
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

  // The chosen planner's entry; InputError for a name nobody registered.
  const PlannerEntry<Space>& entry() const {
    const PlannerEntry<Space>* found = planners<Space>().find(name_);
    if (!found)
      throw InputError(flag_ + ": unknown planner \"" + name_ + "\" (" + planners<Space>().names() + ")");
    return *found;
  }

  // Every option given, checked against the chosen planner: InputError naming the flag for one
  // it does not have, or for one given twice.
  OptionValues values() const {
    const PlannerEntry<Space>& chosen = entry();
    OptionValues values;
    std::set<std::string> given;
    const auto add = [&](const std::string& name, const std::string& value, const std::string& as) {
      bool known = false;
      for (const OptionInfo& o : chosen.options) known |= o.name == name;
      if (!known) throw InputError(as + ": the planner " + chosen.name + " has no option " + name + " (" + option_names(chosen) + ")");
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

  // The planner built for `problem` with the options given.
  std::unique_ptr<Planner<Space>> make(const typename Space::Problem& problem) const { return entry().make(problem, values()); }

 private:
  static std::string option_names(const PlannerEntry<Space>& entry) {
    if (entry.options.empty()) return "it takes none";
    std::string names = "its options:";
    for (const OptionInfo& o : entry.options) names += " " + o.name;
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
  std::vector<std::string> assignments_;
  std::vector<Typed> typed_;
  std::vector<Alias> aliases_;
};

}  // namespace polyplan::cli
