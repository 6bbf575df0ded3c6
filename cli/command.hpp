#pragma once
// What every subcommand shares: how it reports output and which exit codes it uses.
#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace polyplan::cli {

// docs/design.md: 0 for answers (including "no path"), 1 for a path that is not free, 2 for bad input.
enum Exit : int { ok = 0, invalid_path = 1, bad_input = 2, internal_error = 3 };

// Each command registers itself on the app and leaves its action in `run`, called after parsing.
using Action = std::function<int()>;

void add_cspace_command(CLI::App& app, Action& run);
void add_check_command(CLI::App& app, Action& run);
void add_plan_command(CLI::App& app, Action& run);
void add_scen_command(CLI::App& app, Action& run);
void add_grid_command(CLI::App& app, Action& run);
void add_arm_command(CLI::App& app, Action& run);
void add_planners_command(CLI::App& app, Action& run);
void add_steer_command(CLI::App& app, Action& run);
void add_replan_command(CLI::App& app, Action& run);
void add_potential_command(CLI::App& app, Action& run);
void add_ik_command(CLI::App& app, Action& run);
void add_search_command(CLI::App& app, Action& run);
void add_benchmark_command(CLI::App& app, Action& run);

// Writes `value` to `target` ("-" is standard output); throws InputError if it cannot.
void write_json(const nlohmann::json& value, const std::string& target);
// The same for JSON already written out (an ordered_json's dump, whose keys keep their order).
void write_json_text(const std::string& text, const std::string& target);

// "1,2.5,-3" as numbers; throws InputError "OPTION TEXT: "PART" is not a finite number".
std::vector<double> comma_numbers(const std::string& text, const std::string& option);

// "THETA" in degrees as written, reduced exactly into (-180, 180] and then made a double (1e300
// is 0 exactly: 1e300 is a multiple of 360); throws InputError "OPTION TEXT: ..." for text that is
// not a number within the supported range.
double degrees_option(const std::string& text, const std::string& option);

// Prints warnings of the world reader on stderr.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace polyplan::cli
