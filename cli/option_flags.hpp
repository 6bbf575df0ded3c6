#pragma once
// Command-line flags made from option tables (plan/planner_options.hpp), for a planner's options
// (cli/planner_choice.hpp) and a command's own settings alike: one flag per option, --NAME VALUE,
// or --NAME and --no-NAME for a true-or-false option. What a value may be is the table's to say:
// the flags hand it the text given, and its one check refuses a bad value with the option, the
// value and the range or choices ("--weight 0: expected a number in [1, inf)").
#include <polyplan/plan/planner_options.hpp>

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::cli {

class OptionFlags {
 public:
  // Adds the flag of `option`, which --help describes as `help`.
  void add(CLI::App& command, const OptionInfo& option, const std::string& help);
  // NAME=VALUE for every flag given, in the order the flags were added.
  OptionValues given() const;
  // What --help says of an option: "its meaning [its kind] (default D)".
  static std::string help(const OptionInfo& option);

 private:
  struct Flag {
    std::string name;
    std::shared_ptr<std::string> value;
    CLI::Option* option;
  };
  std::vector<Flag> flags_;
};

// A command's settings, declared as a table: `Settings` with its defaults, set from the flags.
template <class Settings>
class CommandOptions {
 public:
  CommandOptions(CLI::App& command, OptionTable<Settings> table) : table_(std::move(table)) {
    for (const OptionInfo& option : table_.info()) flags_.add(command, option, OptionFlags::help(option));
  }
  // The settings given, the others their defaults; InputError for a value the table refuses.
  Settings parse() const { return table_.parse_flags(flags_.given()); }

 private:
  OptionTable<Settings> table_;
  OptionFlags flags_;
};

}  // namespace polyplan::cli
