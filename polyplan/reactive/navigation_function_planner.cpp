#include <polyplan/reactive/navigation_function_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/gradient_descent.hpp>
#include <polyplan/reactive/obstacle_field.hpp>
#include <polyplan/reactive/potential_map.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {
namespace {

struct Sphere {
  Vec2 centre;
  double radius = 0;
};

// The disc around a ring: centre the vertices' centroid, radius the farthest vertex.
Sphere disc_around(const Ring& ring) {
  Vec2 c{0, 0};
  for (const ExactPoint& p : ring) c.x += to_double(p.x), c.y += to_double(p.y);
  c.x /= static_cast<double>(ring.size()), c.y /= static_cast<double>(ring.size());
  double r = 0;
  for (const ExactPoint& p : ring) r = std::max(r, std::hypot(to_double(p.x) - c.x, to_double(p.y) - c.y));
  return {c, r};
}

// Why the discs do not make a sphere world (nullopt when they do).
std::optional<std::string> not_a_sphere_world(const Sphere& world, const std::vector<Sphere>& obstacles) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Sphere& a = obstacles[i];
    if (std::hypot(a.centre.x - world.centre.x, a.centre.y - world.centre.y) + a.radius >= world.radius)
      return "the disc around C-obstacle " + std::to_string(i) + " leaves the world's disc";
    for (std::size_t j = 0; j < i; ++j) {
      const Sphere& b = obstacles[j];
      if (std::hypot(a.centre.x - b.centre.x, a.centre.y - b.centre.y) <= a.radius + b.radius)
        return "the discs around C-obstacles " + std::to_string(j) + " and " + std::to_string(i) + " overlap";
    }
  }
  return std::nullopt;
}

void check_options(const NavigationFunctionOptions& o) {
  if (o.kappa != 0 && !(std::isfinite(o.kappa) && o.kappa >= 1))
    throw std::invalid_argument("kappa: expected 0 (try 2, 4, ..., 64) or a finite number of at least 1, got " +
                                std::to_string(o.kappa));
  if (!(std::isfinite(o.step) && o.step >= 0))
    throw std::invalid_argument("step: expected a finite number of at least 0");
  if (o.patience == 0) throw std::invalid_argument("patience: expected at least 1 step");
}

}  // namespace

struct NavigationFunctionPlanner::Impl {
  const CSpace* cspace;
  NavigationFunctionOptions options;
  ObstacleField field;
  Sphere world;
  std::vector<Sphere> obstacles;
  double step;

  Impl(const CSpace& c, const NavigationFunctionOptions& o) : cspace(&c), options(o), field(c) {
    const BoxGrid box = c.reference_box() && c.reference_box()->xmin <= c.reference_box()->xmax
                            ? BoxGrid{to_double(c.reference_box()->xmin), to_double(c.reference_box()->ymin),
                                      to_double(c.reference_box()->xmax), to_double(c.reference_box()->ymax), 1}
                            : box_around(c, 1);
    // The world's disc: round the box, or without bounds half as wide again round everything.
    const double grow = c.world().bounds ? 1.0 : 1.5;
    world = {{(box.xmin + box.xmax) / 2, (box.ymin + box.ymax) / 2}, grow * box.diagonal() / 2};
    for (const PolygonWithHoles& p : c.cobstacles()) obstacles.push_back(disc_around(p.outer));
    step = o.step > 0 ? o.step : box_around(c, 1).diagonal() / 200;
  }

  // −∇φ's direction at q, as the gradient of a function descended: ∇γ − (γ/κ) Σ ∇βᵢ/βᵢ.
  SlopeAt slope(Vec2 q, Vec2 goal, double kappa) const {
    const double gamma = (q.x - goal.x) * (q.x - goal.x) + (q.y - goal.y) * (q.y - goal.y);
    Vec2 g{2 * (q.x - goal.x), 2 * (q.y - goal.y)};
    const auto add = [&](double beta, Vec2 grad_beta) {
      g.x -= gamma / kappa * grad_beta.x / beta;
      g.y -= gamma / kappa * grad_beta.y / beta;
    };
    const double beta0 = world.radius * world.radius - ((q.x - world.centre.x) * (q.x - world.centre.x) +
                                                        (q.y - world.centre.y) * (q.y - world.centre.y));
    if (!(beta0 > 0)) return {std::nullopt, "the robot is on or beyond the world's disc"};
    add(beta0, {-2 * (q.x - world.centre.x), -2 * (q.y - world.centre.y)});
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const Sphere& s = obstacles[i];
      const double beta =
          (q.x - s.centre.x) * (q.x - s.centre.x) + (q.y - s.centre.y) * (q.y - s.centre.y) - s.radius * s.radius;
      if (!(beta > 0))
        return {std::nullopt, "the robot is inside the disc standing for C-obstacle " + std::to_string(i)};
      add(beta, {2 * (q.x - s.centre.x), 2 * (q.y - s.centre.y)});
    }
    return {Slope{g, gamma, field.clearance(q)}, {}};
  }

  Descent descend(const Query& query, double kappa) const {
    const Vec2 goal = approximate(query.goal);
    return polyplan::descend(*cspace, query, [&](Vec2 q) { return slope(q, goal, kappa); },
                             {step, step, options.max_steps, options.patience, 1e-12});
  }
};

NavigationFunctionPlanner::NavigationFunctionPlanner(const CSpace& cspace, NavigationFunctionOptions options) {
  check_options(options);
  impl_ = std::make_unique<Impl>(cspace, options);
}

NavigationFunctionPlanner::~NavigationFunctionPlanner() = default;

PlanReport<ExactPoint> NavigationFunctionPlanner::plan(const Query& query, const QueryOptions& options) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "navigation-function");
  facts.set(NavigationFacts::spheres, r.obstacles.size());
  const auto finish = [&] {
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  if (answered_before_descent(*r.cspace, query, report)) return finish();
  if (auto why = not_a_sphere_world(r.world, r.obstacles)) {
    report.fail(PlanStatus::not_found, "not a sphere world: " + *why);
    return finish();
  }
  Descent descent;
  double kappa = r.options.kappa;
  for (const double k :
       r.options.kappa > 0 ? std::vector<double>{r.options.kappa} : std::vector<double>{2, 4, 8, 16, 32, 64}) {
    kappa = k;
    descent = r.descend(query, k);
    if (descent.status == PlanStatus::solved || descent.status == PlanStatus::not_found) break;
  }
  facts.set(NavigationFacts::kappa, kappa);
  report_descent(*r.cspace, std::move(descent), NavigationFacts::descent, options.record,
                 " (kappa " + std::to_string(kappa) + ")", report);
  return finish();
}

PlannerEntry<TranslatingRobot> navigation_function_planner_entry() {
  OptionTable<NavigationFunctionOptions> table;
  table
      .add("kappa", &NavigationFunctionOptions::kappa,
           "the navigation function's kappa (0: the smallest of 2, 4, ..., 64 that reaches the goal)", at_least(0))
      .add("step", &NavigationFunctionOptions::step, "the longest step (0: 1/200 of the world's diagonal)", at_least(0))
      .add("max-steps", &NavigationFunctionOptions::max_steps, "steps before the descent stops with status limit",
           at_least(1))
      .add("patience", &NavigationFunctionOptions::patience,
           "steps without getting closer to the goal before it is a local minimum", at_least(1));
  return make_planner_entry<TranslatingRobot, NavigationFunctionOptions>(
      "navigation-function",
      "descent on Rimon and Koditschek's navigation function of the discs around the C-obstacles (sphere worlds)",
      std::move(table), [](const CSpace& cspace, const NavigationFunctionOptions& o) {
        return std::make_unique<NavigationFunctionPlanner>(cspace, o);
      });
}

}  // namespace polyplan
