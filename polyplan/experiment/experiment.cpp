#include <polyplan/experiment/experiment.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
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

void scale_experiment(Experiment& e, std::size_t seeds, double time_limit, const std::string& seeds_name) {
  if (seeds) {
    if (seeds > e.seeds.size())
      throw InputError(seeds_name + " " + std::to_string(seeds) + ": the experiment has " +
                       std::to_string(e.seeds.size()) + " seeds");
    e.seeds.resize(seeds);
  }
  if (time_limit > 0) {
    for (double& t : e.cost_times) t *= time_limit / e.time_limit;
    e.time_limit = time_limit;
  }
}

}  // namespace polyplan
