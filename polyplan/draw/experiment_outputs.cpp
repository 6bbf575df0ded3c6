#include <polyplan/draw/experiment_outputs.hpp>

#include <polyplan/draw/experiment_plots.hpp>
#include <polyplan/experiment/experiment_results.hpp>
#include <polyplan/experiment/experiment_statistics.hpp>
#include <polyplan/experiment/experiment_tables.hpp>
#include <polyplan/experiment/ompl_benchmark_log.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>

namespace polyplan {
namespace {

namespace fs = std::filesystem;

// Checked after closing: a full disk fails only when the buffer is written.
void write_text(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path);
  if (out) write(out);
  if (out) out.close();
  if (!out) throw InputError(path.string() + ": cannot write");
}

void write_picture(const svg::Drawing& drawing, const fs::path& path) {
  try {
    drawing.write(path.string());
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

}  // namespace

std::string file_name_part(const std::string& name) {
  std::string part;
  for (char c : name) part += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  return part;
}

std::vector<std::string> write_experiment_outputs(const std::string& folder, const Experiment& experiment,
                                                  const ExperimentResults& results) {
  const fs::path out(folder);
  std::error_code error;
  fs::create_directories(out, error);
  if (error || !fs::is_directory(out)) throw InputError(folder + ": cannot make the folder");
  std::vector<std::string> written;
  const auto text = [&](const std::string& name, const std::function<void(std::ostream&)>& write) {
    write_text(out / name, write);
    written.push_back((out / name).string());
  };
  text("results.log", [&](std::ostream& o) { write_ompl_benchmark_log(o, experiment, results); });
  text("results.json", [&](std::ostream& o) { o << experiment_results_json(experiment, results).dump(2) << '\n'; });
  text("results.csv", [&](std::ostream& o) { write_experiment_results_csv(o, experiment, results); });
  text("tables.md", [&](std::ostream& o) { write_experiment_tables(o, experiment, results); });

  const auto picture = [&](const svg::Drawing& drawing, const std::string& name) {
    write_picture(drawing, out / name);
    written.push_back((out / name).string());
  };
  const auto statistics = experiment_statistics(experiment, results);
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem) {
    const std::string name = file_name_part(experiment.problems[problem].name);
    const auto& cells = statistics[problem];
    picture(success_rate_plot(experiment, problem, cells), name + "-success.svg");
    if (auto cost = cost_over_time_plot(experiment, problem, cells)) picture(*cost, name + "-cost.svg");
    picture(box_plot(experiment, problem, cells, BoxPlotOf::time), name + "-time.svg");
    picture(box_plot(experiment, problem, cells, BoxPlotOf::length), name + "-length.svg");
  }
  return written;
}

}  // namespace polyplan
