// polyplan: the command-line program. Each subcommand lives in its own file.
#include "cli/command.hpp"
#include "cli/process_limits.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <fstream>
#include <iostream>
#include <new>

namespace polyplan::cli {

void write_json_text(const std::string& text, const std::string& target) {
  // Checked after flushing: a full disk (or /dev/full) fails only when the buffer is written.
  if (target == "-") {
    std::cout << text << '\n' << std::flush;
    if (!std::cout) throw InputError("standard output: cannot write the JSON output");
    return;
  }
  std::ofstream out(target);
  if (out) out << text << '\n';
  if (out) out.close();
  if (!out) throw InputError(target + ": cannot write the JSON output");
}

void write_json(const nlohmann::json& value, const std::string& target) { write_json_text(value.dump(2), target); }

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "warning: " << w << '\n';
}

}  // namespace polyplan::cli

int main(int argc, char** argv) {
  using namespace polyplan::cli;
  CLI::App app{"polyplan: exact motion planning in polygon worlds"};
  app.require_subcommand(1);
  Action run;
  const auto limits = add_process_limits(app);  // first: the commands added after it pass them up
  add_cspace_command(app, run);
  add_check_command(app, run);
  add_plan_command(app, run);
  add_scen_command(app, run);
#if POLYPLAN_WITH_GRIDS  // the commands of a family this build leaves out (cmake -DPOLYPLAN_FAMILIES) are not in it
  add_grid_command(app, run);
#endif
  add_arm_command(app, run);
  add_planners_command(app, run);
#if POLYPLAN_WITH_CAR
  add_steer_command(app, run);
#endif
#if POLYPLAN_WITH_INCREMENTAL
  add_replan_command(app, run);
#endif
#if POLYPLAN_WITH_REACTIVE
  add_potential_command(app, run);
#endif
#if POLYPLAN_WITH_ARM
  add_ik_command(app, run);
#endif
  add_search_command(app, run);
  add_benchmark_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line, like every other bad input, naming what was not understood.
    std::string message = e.what();
    if (argc > 1 && argv[1][0] != '-' &&
        app.get_subcommands([&](const CLI::App* c) { return c->get_name() == argv[1]; }).empty()) {
      message = "unknown command \"" + std::string(argv[1]) + "\" (commands:";
      for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; }))
        message += " " + c->get_name();
      message += ")";
      if (const std::string left_out = polyplan::families_left_out(); !left_out.empty())
        message += "; this polyplan is built without the " + left_out + " planners (cmake -DPOLYPLAN_FAMILIES=all)";
    }
    std::cerr << "error: " << message << " (see polyplan --help)\n";
    return bad_input;
  }
  apply_process_limits(*limits);
  try {
    return run();
  } catch (const polyplan::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return bad_input;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: " << out_of_memory_message(*limits) << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "internal error (please report): " << e.what() << '\n';
    return internal_error;
  }
}
