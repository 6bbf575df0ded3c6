#include <polyplan/reactive/potential_field_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/gradient_descent.hpp>
#include <polyplan/reactive/potential_map.hpp>
#include <polyplan/reactive/potential_study.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

void check_options(const PotentialFieldOptions& o) {
  const auto weight = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0)
      throw std::invalid_argument(std::string(name) + ": expected a finite number of at least 0, got " +
                                  std::to_string(v));
  };
  weight(o.zeta, "zeta");
  weight(o.d_star, "d-star");
  weight(o.eta, "eta");
  weight(o.q_star, "q-star");
  weight(o.step, "step");
  weight(o.goal_tolerance, "goal-tolerance");
  if (o.zeta == 0) throw std::invalid_argument("zeta: 0 leaves no attraction to the goal");
  if (o.patience == 0) throw std::invalid_argument("patience: expected at least 1 step");
}

}  // namespace

struct PotentialFieldPlanner::Impl {
  const CSpace* cspace;
  DescentWorld exact;
  PotentialFieldOptions options;
  PotentialParameters parameters;
  ObstacleField field;
  double step, tolerance;

  Impl(const CSpace& c, const PotentialFieldOptions& o)
      : cspace(&c), exact(descent_world(c)), options(o), parameters{{o.zeta, o.d_star}, {o.eta, o.q_star}}, field(c),
        step(o.step > 0 ? o.step : box_around(c, 1).diagonal() / 200),
        tolerance(o.goal_tolerance > 0 ? o.goal_tolerance : step) {}

  Descent descend(const Query& query) const {
    const Vec2 goal = approximate(query.goal);
    const SlopeFunction slope = [&](Vec2 q) -> SlopeAt {
      const std::vector<NearestPoint> nearest = field.nearest_points(q);
      const double clearance = ObstacleField::clearance(nearest);
      if (clearance == 0)
        return {std::nullopt, "the robot touches an obstacle, where the repulsion is infinite and has no gradient"};
      const Potential p = ObstacleField::potential(q, goal, parameters, nearest);
      return {Slope{p.gradient, p.value, clearance}, {}};
    };
    return polyplan::descend(exact, query, slope,
                             {step, tolerance, options.max_steps, options.patience, 1e-12 * (options.zeta + 1)});
  }

  // log(1 + U) over a 64 × 64 grid of the box around the world, for the picture.
  std::shared_ptr<const CellGrid> heat_map(const Query& query) const {
    return std::make_shared<const CellGrid>(
        potential_map(*cspace, field, approximate(query.goal), parameters, box_around(*cspace, 64)));
  }
};

PotentialFieldPlanner::PotentialFieldPlanner(const CSpace& cspace, PotentialFieldOptions options) {
  check_options(options);
  impl_ = std::make_unique<Impl>(cspace, options);
}

PotentialFieldPlanner::~PotentialFieldPlanner() = default;

PlanReport<ExactPoint> PotentialFieldPlanner::plan(const Query& query, const QueryOptions& options) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "potential-field");
  facts.set(PotentialFacts::step, r.step);
  const auto finish = [&] {
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  if (options.record) report.recording.cells = r.heat_map(query);
  if (answered_before_descent(r.exact, query, report)) return finish();
  Descent descent = r.descend(query);
  facts.set(PotentialFacts::gradient, std::hypot(descent.last.gradient.x, descent.last.gradient.y));
  facts.set(PotentialFacts::value, descent.last.value);
  report_descent(r.exact, std::move(descent), PotentialFacts::descent, options.record, "", report);
  return finish();
}

PlannerEntry<TranslatingRobot> potential_field_planner_entry() {
  OptionTable<PotentialFieldOptions> table;
  add_potential_weights(table)
      .add("step", &PotentialFieldOptions::step, "the longest step (0: 1/200 of the world's diagonal)", at_least(0))
      .add("goal-tolerance", &PotentialFieldOptions::goal_tolerance,
           "solved within this distance of the goal (0: the step)", at_least(0))
      .add("max-steps", &PotentialFieldOptions::max_steps, "steps before the descent stops with status limit",
           at_least(1))
      .add("patience", &PotentialFieldOptions::patience,
           "steps without getting closer to the goal before it is a local minimum", at_least(1));
  return make_planner_entry<TranslatingRobot, PotentialFieldOptions>(
      "potential-field",
      "gradient descent on the goal's attraction and each C-obstacle's repulsion (Choset et al. ch. 4)",
      std::move(table), [](const CSpace& cspace, const PotentialFieldOptions& o) {
        return std::make_unique<PotentialFieldPlanner>(cspace, o);
      });
}

}  // namespace polyplan
