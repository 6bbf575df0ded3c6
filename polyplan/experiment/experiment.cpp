#include <polyplan/experiment/experiment.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {

double ExperimentRun::cost_at(double at) const {
  double best = std::numeric_limits<double>::infinity();
  for (const SolutionImprovement& i : improvements)
    if (i.seconds <= at) best = std::min(best, i.length);
  return best;
}

double ExperimentRun::first_solution_seconds() const {
  return improvements.empty() ? std::numeric_limits<double>::infinity() : improvements.front().seconds;
}

void scale_experiment(Experiment& e, std::size_t seeds, double time_limit, const std::string& seeds_name,
                      const std::string& limit_name) {
  if (seeds) {
    if (seeds > e.seeds.size())
      throw InputError(seeds_name + " " + std::to_string(seeds) + ": the experiment has " +
                       std::to_string(e.seeds.size()) + " seeds");
    e.seeds.resize(seeds);
  }
  if (time_limit > 0) {
    std::vector<double> scaled = e.cost_times;
    for (double& t : scaled) t *= time_limit / e.time_limit;
    // A ratio of 1e300 or 1e-300 would round the times to infinity or to 0: refused, not written.
    for (std::size_t i = 0; i < scaled.size(); ++i)
      if (!std::isfinite(scaled[i]) || scaled[i] <= 0 || (i > 0 && scaled[i] <= scaled[i - 1]))
        throw InputError(limit_name + " " + detail::show_number(time_limit) +
                         ": scales the experiment's cost times out of what a double holds apart");
    e.cost_times = std::move(scaled);
    e.time_limit = time_limit;
  }
}

}  // namespace polyplan
