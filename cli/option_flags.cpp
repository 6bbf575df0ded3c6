#include "cli/option_flags.hpp"

namespace polyplan::cli {

void OptionFlags::add(CLI::App& command, const OptionInfo& option, const std::string& help) {
  auto value = std::make_shared<std::string>();
  const std::string& name = option.name;
  CLI::Option* flag = option.flag ? command.add_flag("--" + name + "{true},--no-" + name + "{false}", *value, help)
                                  : command.add_option("--" + name, *value, help)->type_name("VALUE");
  flags_.push_back({name, value, flag});
}

OptionValues OptionFlags::given() const {
  OptionValues values;
  for (const Flag& f : flags_)
    if (f.option->count() > 0) values.emplace_back(f.name, *f.value);
  return values;
}

std::string OptionFlags::help(const OptionInfo& option) {
  return option.description + " [" + option.kind + "] (default " + option.default_value + ")";
}

}  // namespace polyplan::cli
