// polyplan: the command-line program. Each subcommand lives in its own file.
#include "cli/command.hpp"

#include <polyplan/geometry/input_error.hpp>

#include <fstream>
#include <iostream>

namespace polyplan::cli {

void write_json(const nlohmann::json& value, const std::string& target) {
  if (target == "-") {
    std::cout << value.dump(2) << '\n';
    return;
  }
  std::ofstream out(target);
  if (!out || !(out << value.dump(2) << '\n')) throw InputError(target + ": cannot write the JSON output");
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "warning: " << w << '\n';
}

}  // namespace polyplan::cli

int main(int argc, char** argv) {
  using namespace polyplan::cli;
  CLI::App app{"polyplan: exact motion planning in polygon worlds"};
  app.require_subcommand(1);
  Action run;
  add_cspace_command(app, run);
  add_check_command(app, run);
  add_plan_command(app, run);
  add_scen_command(app, run);
  add_grid_command(app, run);
  add_arm_command(app, run);
  add_planners_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? ok : bad_input;
  }
  try {
    return run();
  } catch (const polyplan::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "internal error (please report): " << e.what() << '\n';
    return internal_error;
  }
}
