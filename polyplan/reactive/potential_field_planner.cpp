#include <polyplan/reactive/potential_field_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/gradient_descent.hpp>
#include <polyplan/reactive/potential_map.hpp>
#include <polyplan/reactive/potential_study.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/round_obstacle_field.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace polyplan {
// The descent both planners share (a polygon world's C-space, a round world); named, as their
// Impl hold it.
namespace potential_detail {

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

// What a potential field descends: the exact tests, the obstacles that repel, and the box round
// the world (the default step's measure, the picture's frame) with the test of its cells.
struct FieldDescent {
  DescentWorld exact;
  PotentialFieldOptions options;
  PotentialParameters parameters;
  const Repellers* field;
  BoxGrid box;  // 64 cells a side, for the picture
  std::function<bool(const ExactPoint&)> is_free;
  double step, tolerance;

  FieldDescent(DescentWorld w, const PotentialFieldOptions& o, const Repellers& f, BoxGrid b,
               std::function<bool(const ExactPoint&)> free)
      : exact(std::move(w)), options(o), parameters{{o.zeta, o.d_star}, {o.eta, o.q_star}}, field(&f), box(b),
        is_free(std::move(free)), step(o.step > 0 ? o.step : box.diagonal() / 200),
        tolerance(o.goal_tolerance > 0 ? o.goal_tolerance : step) {}

  Descent descend(const Query& query) const {
    const Vec2 goal = approximate(query.goal);
    const SlopeFunction slope = [&](Vec2 q) -> SlopeAt {
      const std::vector<NearestPoint> nearest = field->nearest_points(q);
      const double clearance = Repellers::clearance(nearest);
      // Not above 0 (rounding may make a touching rim's distance a hair below it): in contact.
      if (!(clearance > 0))
        return {std::nullopt, "the robot touches an obstacle, where the repulsion is infinite and has no gradient"};
      const Potential p = Repellers::potential(q, goal, parameters, nearest);
      return {Slope{p.gradient, p.value, clearance}, {}};
    };
    return polyplan::descend(exact, query, slope,
                             {step, tolerance, options.max_steps, options.patience, 1e-12 * (options.zeta + 1)});
  }

  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& query_options) const {
    const Stopwatch querying;
    PlanReport<ExactPoint> report;
    Facts& facts = report.facts;
    facts.set(RoadmapFacts::kind, "potential-field");
    facts.set(PotentialFacts::step, step);
    const auto finish = [&] {
      facts.set(QueryFacts::seconds, querying.seconds());
      return std::move(report);
    };
    // log(1 + U) over a 64 × 64 grid of the box around the world, for the picture.
    if (query_options.record)
      report.recording.cells =
          std::make_shared<const CellGrid>(potential_map(is_free, *field, approximate(query.goal), parameters, box));
    if (answered_before_descent(exact, query, report)) return finish();
    Descent descent = descend(query);
    facts.set(PotentialFacts::gradient, std::hypot(descent.last.gradient.x, descent.last.gradient.y));
    facts.set(PotentialFacts::value, descent.last.value);
    report_descent(exact, std::move(descent), PotentialFacts::descent, query_options.record, "", report);
    return finish();
  }
};

OptionTable<PotentialFieldOptions> potential_field_options() {
  OptionTable<PotentialFieldOptions> table;
  add_potential_weights(table)
      .add("step", &PotentialFieldOptions::step, "the longest step (0: 1/200 of the world's diagonal)", at_least(0))
      .add("goal-tolerance", &PotentialFieldOptions::goal_tolerance,
           "solved within this distance of the goal (0: the step)", at_least(0))
      .add("max-steps", &PotentialFieldOptions::max_steps, "steps before the descent stops with status limit",
           at_least(1))
      .add("patience", &PotentialFieldOptions::patience,
           "steps without getting closer to the goal before it is a local minimum", at_least(1));
  return table;
}

}  // namespace potential_detail

using potential_detail::FieldDescent;

struct PotentialFieldPlanner::Impl {
  ObstacleField field;
  FieldDescent descent;

  Impl(const CSpace& c, const PotentialFieldOptions& o)
      : field(c), descent(descent_world(c), o, field, box_around(c, 64),
                          [&c](const ExactPoint& p) { return c.locate(p).kind == Location::Kind::free; }) {}
};

PotentialFieldPlanner::PotentialFieldPlanner(const CSpace& cspace, PotentialFieldOptions options) {
  potential_detail::check_options(options);
  impl_ = std::make_unique<Impl>(cspace, options);
}

PotentialFieldPlanner::~PotentialFieldPlanner() = default;

PlanReport<ExactPoint> PotentialFieldPlanner::plan(const Query& query, const QueryOptions& options) {
  return impl_->descent.plan(query, options);
}

PlannerEntry<TranslatingRobot> potential_field_planner_entry() {
  return make_planner_entry<TranslatingRobot, PotentialFieldOptions>(
      "potential-field",
      "gradient descent on the goal's attraction and each C-obstacle's repulsion (Choset et al. ch. 4)",
      potential_detail::potential_field_options(), [](const CSpace& cspace, const PotentialFieldOptions& o) {
        return std::make_unique<PotentialFieldPlanner>(cspace, o);
      });
}

struct RoundPotentialFieldPlanner::Impl {
  RoundObstacleField field;
  FieldDescent descent;

  Impl(const RoundWorld& w, const PotentialFieldOptions& o)
      : field(w), descent(descent_world(w), o, field, box_around(w, 64),
                          [&w](const ExactPoint& p) { return !w.config_not_free(p); }) {}
};

RoundPotentialFieldPlanner::RoundPotentialFieldPlanner(const RoundWorld& world, PotentialFieldOptions options) {
  potential_detail::check_options(options);
  impl_ = std::make_unique<Impl>(world, options);
}

RoundPotentialFieldPlanner::~RoundPotentialFieldPlanner() = default;

PlanReport<ExactPoint> RoundPotentialFieldPlanner::plan(const Query& query, const QueryOptions& options) {
  return impl_->descent.plan(query, options);
}

PlannerEntry<RoundRobot> round_potential_field_planner_entry() {
  return make_planner_entry<RoundRobot, PotentialFieldOptions>(
      "potential-field",
      "gradient descent on the goal's attraction and each disc's, wall's and polygon's repulsion, from the "
      "distance the robot keeps from it (Choset et al. ch. 4)",
      potential_detail::potential_field_options(), [](const RoundWorld& world, const PotentialFieldOptions& o) {
        return std::make_unique<RoundPotentialFieldPlanner>(world, o);
      });
}

}  // namespace polyplan
