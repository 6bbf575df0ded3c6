#include <polyplan/reactive/potential_field_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/potential_map.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

std::string point_text(Vec2 p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

void check_options(const PotentialFieldOptions& o) {
  const auto weight = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0) throw std::invalid_argument(std::string(name) + ": expected a finite number of at least 0, got " + std::to_string(v));
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
  PotentialFieldOptions options;
  PotentialParameters parameters;
  ObstacleField field;
  double step, tolerance;

  Impl(const CSpace& c, const PotentialFieldOptions& o)
      : cspace(&c), options(o), parameters{{o.zeta, o.d_star}, {o.eta, o.q_star}}, field(c),
        step(o.step > 0 ? o.step : box_around(c, 1).diagonal() / 200), tolerance(o.goal_tolerance > 0 ? o.goal_tolerance : step) {}

  // One step from `at` along `direction`, at most `length` long: halved until its segment is
  // exactly free (a step that started in the free space always ends so, at some length).
  std::optional<ExactPoint> free_step(const ExactPoint& at, Vec2 from, Vec2 direction, double length) const {
    for (int halvings = 0; halvings < 60; ++halvings, length /= 2) {
      const ExactPoint to = exactly({from.x + length * direction.x, from.y + length * direction.y});
      if (check_segment(*cspace, at, to).valid) return to;
    }
    return std::nullopt;
  }

  struct Descent {
    std::vector<ExactPoint> path;
    PlanStatus status = PlanStatus::limit;
    std::string why;
    Potential last;
  };

  Descent descend(const Query& query) const {
    Descent d;
    d.path = {query.start};
    const Vec2 goal = approximate(query.goal);
    Vec2 q = approximate(query.start), previous_direction{0, 0};
    double current = step, best = distance(q, goal);
    std::size_t since_best = 0;
    for (std::size_t k = 0; k < options.max_steps; ++k) {
      if (distance(q, goal) <= tolerance) {
        if (check_segment(*cspace, d.path.back(), query.goal).valid) {
          d.path.push_back(query.goal);
          d.status = PlanStatus::solved;
        } else {
          d.status = PlanStatus::not_found;
          d.why = "within the goal tolerance at " + point_text(q) + ", but the straight step to the goal is not free";
        }
        return d;
      }
      if (field.clearance(q) == 0) {  // the repulsion is infinite in contact: no gradient to follow
        d.status = PlanStatus::not_found;
        d.why = "at " + point_text(q) + " the robot touches an obstacle, where the repulsion is infinite and has no gradient";
        return d;
      }
      d.last = field.potential(q, goal, parameters);
      const double g = std::hypot(d.last.gradient.x, d.last.gradient.y);
      if (!(g > 1e-12 * (options.zeta + 1))) return stop(d, q, "the gradient vanishes");
      const Vec2 direction{-d.last.gradient.x / g, -d.last.gradient.y / g};
      // A sharp turn means the gradient changes fast here: shorter steps; a straight run, longer.
      current = direction.x * previous_direction.x + direction.y * previous_direction.y < 0.5 && k > 0 ? current / 2
                                                                                                         : std::min(step, current * 1.25);
      previous_direction = direction;
      if (current < 1e-9 * step) return stop(d, q, "its steps shrank to nothing");
      const double length = std::min({current, distance(q, goal), field.clearance(q) / 2});
      const auto to = free_step(d.path.back(), q, direction, length);
      if (!to) return stop(d, q, "no step along the gradient is free");
      d.path.push_back(*to);
      q = approximate(*to);
      if (distance(q, goal) < best * (1 - 1e-9)) {
        best = distance(q, goal);
        since_best = 0;
      } else if (++since_best >= options.patience) {
        return stop(d, q, std::to_string(options.patience) + " steps brought it no closer to the goal (it oscillates)");
      }
    }
    d.why = "the step limit (" + std::to_string(options.max_steps) + ") ended the descent at " + point_text(q);
    return d;
  }

  static Descent& stop(Descent& d, Vec2 q, const std::string& why) {
    d.status = PlanStatus::local_minimum;
    d.why = "a local minimum of the potential at " + point_text(q) + ": " + why;
    return d;
  }

  // log(1 + U) over a 64 × 64 grid of the box around the world, for the picture.
  std::shared_ptr<const CellGrid> heat_map(const Query& query) const {
    return std::make_shared<const CellGrid>(potential_map(*cspace, field, approximate(query.goal), parameters, box_around(*cspace, 64)));
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
  facts.set("roadmap.kind", "potential-field");
  facts.set("potential.step", r.step);
  const auto finish = [&] {
    facts.set("query_seconds", querying.seconds());
    return std::move(report);
  };
  if (options.record) report.cells = r.heat_map(query);
  if (auto why = r.cspace->query_not_free(query)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish();
  }
  if (!share_a_component(*r.cspace, query.start, query.goal)) {
    report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
    return finish();
  }
  Impl::Descent descent = r.descend(query);
  if (options.record) report.expanded = descent.path;  // the picture shows the descent, wherever it stopped
  const Vec2 stopped = approximate(descent.path.back());
  facts.set("potential.steps", descent.path.size() - 1);
  facts.set("potential.stopped_at", point_text(stopped));
  facts.set("potential.gradient", std::hypot(descent.last.gradient.x, descent.last.gradient.y));
  facts.set("potential.value", descent.last.value);
  if (descent.status != PlanStatus::solved) {
    if (descent.status == PlanStatus::limit) facts.set("stopped_by", "step limit");
    report.fail(descent.status, descent.why);
    return finish();
  }
  report.succeed();
  report.path = std::move(descent.path);
  report.length = euclidean_length(report.path);
  report.certificate = {true, "exact segment test of every step as it was taken (arrangement zone walk)"};
  return finish();
}

PlannerEntry<TranslatingRobot> potential_field_planner_entry() {
  OptionTable<PotentialFieldOptions> table;
  table.add("zeta", &PotentialFieldOptions::zeta, "weight of the goal's attraction")
      .add("d-star", &PotentialFieldOptions::d_star, "quadratic attraction within this distance of the goal, conic beyond (0: conic everywhere)")
      .add("eta", &PotentialFieldOptions::eta, "weight of each obstacle's repulsion")
      .add("q-star", &PotentialFieldOptions::q_star, "an obstacle farther than this does not repel")
      .add("step", &PotentialFieldOptions::step, "the longest step (0: 1/200 of the world's diagonal)")
      .add("goal-tolerance", &PotentialFieldOptions::goal_tolerance, "solved within this distance of the goal (0: the step)")
      .add("max-steps", &PotentialFieldOptions::max_steps, "steps before the descent stops with status limit")
      .add("patience", &PotentialFieldOptions::patience, "steps without getting closer to the goal before it is a local minimum");
  return make_planner_entry<TranslatingRobot, PotentialFieldOptions>(
      "potential-field", "gradient descent on the goal's attraction and each C-obstacle's repulsion (Choset et al. ch. 4)",
      std::move(table), [](const CSpace& cspace, const PotentialFieldOptions& o) { return std::make_unique<PotentialFieldPlanner>(cspace, o); });
}

}  // namespace polyplan
