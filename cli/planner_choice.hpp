#pragma once
// How a command picks a planner and sets its options, for every planner of the registry alike:
// `--planner NAME` (and the aliases older scripts use), `--option NAME=VALUE` (repeatable), and
// `--NAME VALUE` for every option name some planner has (`--NAME` / `--no-NAME` for
// true-or-false options). The flags come from the front door's catalog (registry/any_planner.hpp),
// so a new planner's options reach the command line without code here; which planner a name is,
// and the default, the door settles for the problem read.
#include "cli/option_flags.hpp"

#include <polyplan/plan/planner_options.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <CLI/CLI.hpp>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace polyplan::cli {

class PlannerChoice {
 public:
  // `flag` is the primary flag ("--planner"); `aliases` name it too ("--roadmap", "--method").
  // Made after the command's own flags: a planner option that would shadow one is a
  // std::logic_error (a planner's option must be renamed, or the command's flag).
  PlannerChoice(CLI::App& command, const std::string& flag, const std::vector<std::string>& aliases);

  // Another spelling of one option's value (`--eager` for evaluation=eager): a flag that sets it.
  CLI::Option* add_alias(CLI::App& command, const std::string& alias, const std::string& option,
                         const std::string& value, const std::string& help);

  // Settles the planner for `problem`: the one named, or the problem's default. InputError for a
  // name nobody registered or one that does not plan this problem, an option the planner does
  // not have or one given twice — before anything is built.
  void choose_for(const Problem& problem);

  // After choose_for: the planner's name, the options given, the planner built.
  const std::string& name() const { return name_; }
  const OptionValues& values() const { return values_; }
  std::unique_ptr<AnyPlanner> make(const Problem& problem) const { return make_planner(name_, problem, values_); }
  // " · resolution 2 · seed 3": the options given, for a picture's title.
  std::string settings() const;

 private:
  OptionValues given(const PlannerListing& planner) const;

  struct Alias {
    std::string option, value;
    std::shared_ptr<bool> given;
    std::string flag;
  };

  std::string flag_;
  std::string name_;
  OptionValues values_;
  CLI::Option* chosen_ = nullptr;
  std::vector<std::string> assignments_;
  OptionFlags flags_;  // one per option name, whichever planners have it
  std::vector<Alias> aliases_;
};

}  // namespace polyplan::cli
