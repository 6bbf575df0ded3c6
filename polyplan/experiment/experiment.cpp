#include <polyplan/experiment/experiment.hpp>

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

}  // namespace polyplan
