#pragma once
// What bounds every command, whatever it does: --max-memory-mb and --max-seconds, given before or
// after the command's name. The commands whose work can outgrow their input's limits have budgets
// of their own that end the work with an answer (status `limit`: the planners' `time`, replan's
// --time-limit and --memory-mb, the arm grid's memory-mb); these two are the floor under all of
// them, so that no input within the documented limits runs without end or takes the machine's
// memory: past them the program stops with exit 2 and one line naming the limit.
#include <CLI/CLI.hpp>

#include <memory>

namespace polyplan::cli {

struct ProcessLimits {
  double max_memory_mb = 16384;  // the address space the program may take (not under AddressSanitizer)
  double max_seconds = 3600;     // wall-clock seconds
};

// Adds the two flags to the program and returns where their values land once parsed. Called
// before the commands are added: they inherit CLI11's fallthrough, which passes the flags up.
std::shared_ptr<ProcessLimits> add_process_limits(CLI::App& app);

// Caps the address space and starts the watchdog that ends the program after max_seconds.
void apply_process_limits(const ProcessLimits& limits);

// The line for an allocation that failed: the memory budget, and the flag that raises it.
std::string out_of_memory_message(const ProcessLimits& limits);

}  // namespace polyplan::cli
