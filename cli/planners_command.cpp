// polyplan planners [--json FILE|-]: every registered planner with its description and options.
#include "cli/command.hpp"

#include <polyplan/registry/any_planner.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace polyplan::cli {
namespace {

struct PlannersCommand {
  std::string json;
};

// An end of a range: null when unbounded.
nlohmann::json range_end(double x) { return std::isinf(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }

nlohmann::json option_json(const OptionInfo& o) {
  nlohmann::json option = {{"name", o.name},
                           {"description", o.description},
                           {"kind", o.kind},
                           {"default", o.default_value},
                           {"flag", o.flag}};
  if (o.range)
    option["range"] = {{"min", range_end(o.range->min)},
                       {"max", range_end(o.range->max)},
                       {"min_open", o.range->min_open},
                       {"max_open", o.range->max_open},
                       {"text", o.range->text()}};
  if (!o.choices.empty()) option["choices"] = o.choices;
  return option;
}

// The catalog by space, in its order: {space, command, planners [{name, description, options}]}.
nlohmann::json spaces_json() {
  nlohmann::json spaces = nlohmann::json::array();
  for (const PlannerListing& planner : planner_catalog()) {
    if (spaces.empty() || spaces.back()["space"] != planner.space)
      spaces.push_back({{"space", planner.space},
                        {"command", "polyplan plan " + planner.file + " --planner NAME"},
                        {"planners", nlohmann::json::array()}});
    nlohmann::json options = nlohmann::json::array();
    for (const OptionInfo& o : planner.options) options.push_back(option_json(o));
    spaces.back()["planners"].push_back(
        {{"name", planner.name}, {"description", planner.description}, {"options", options}});
  }
  return spaces;
}

void print_space(const nlohmann::json& space) {
  std::cout << "Planners for " << space["space"].get<std::string>() << " (" << space["command"].get<std::string>()
            << "):\n";
  for (const auto& planner : space["planners"]) {
    std::printf("  %-16s %s\n", planner["name"].get<std::string>().c_str(),
                planner["description"].get<std::string>().c_str());
    for (const auto& o : planner["options"]) {
      const std::string name = o["name"], kind = o["kind"];
      const std::string flag = o["flag"].get<bool>() ? "--" + name + ", --no-" + name : "--" + name + " " + kind;
      std::printf("      %s   (default %s)\n          %s\n", flag.c_str(), o["default"].get<std::string>().c_str(),
                  o["description"].get<std::string>().c_str());
    }
  }
}

int run_planners(const PlannersCommand& command) {
  const nlohmann::json spaces = spaces_json();
  if (!command.json.empty()) write_json(spaces, command.json);
  if (command.json != "-") {
    for (std::size_t i = 0; i < spaces.size(); ++i) {
      if (i > 0) std::cout << '\n';
      print_space(spaces[i]);
    }
    std::cout << "\nSet an option as --NAME VALUE or --option NAME=VALUE (true-or-false options: --NAME, --no-NAME).\n";
  }
  return ok;
}

}  // namespace

void add_planners_command(CLI::App& app, Action& run) {
  auto command = std::make_shared<PlannersCommand>();
  CLI::App* planners = app.add_subcommand("planners", "List every planner with its description and options");
  planners->add_option("--json", command->json, "Write the list as JSON to this file ('-' for standard output)");
  planners->callback([command, &run] { run = [command] { return run_planners(*command); }; });
}

}  // namespace polyplan::cli
