#include <polyplan/reactive/navigation_function_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/reactive/gradient_descent.hpp>
#include <polyplan/reactive/obstacle_field.hpp>
#include <polyplan/reactive/potential_map.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {
// The sphere-world machinery both planners share; named, as the planners' Impl hold it.
namespace navigation_detail {

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

// What a navigation function descends: the world's disc, the obstacles' discs, the exact tests,
// the step and a clearance for capping steps; or why the world is no sphere world.
struct SphereNavigation {
  DescentWorld exact;
  NavigationFunctionOptions options;
  Sphere world;
  std::vector<Sphere> obstacles;
  double step = 1;
  std::function<double(Vec2)> clearance;
  std::optional<std::string> not_spheres;  // a world that cannot be one: why

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
    return {Slope{g, gamma, clearance(q)}, {}};
  }

  Descent descend(const Query& query, double kappa) const {
    const Vec2 goal = approximate(query.goal);
    return polyplan::descend(exact, query, [&](Vec2 q) { return slope(q, goal, kappa); },
                             {step, step, options.max_steps, options.patience, 1e-12});
  }

  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& query_options) const {
    const Stopwatch querying;
    PlanReport<ExactPoint> report;
    Facts& facts = report.facts;
    facts.set(RoadmapFacts::kind, "navigation-function");
    facts.set(NavigationFacts::spheres, obstacles.size());
    const auto finish = [&] {
      facts.set(QueryFacts::seconds, querying.seconds());
      return std::move(report);
    };
    if (answered_before_descent(exact, query, report)) return finish();
    if (auto why = not_spheres ? not_spheres : not_a_sphere_world(world, obstacles)) {
      report.fail(PlanStatus::not_found, "not a sphere world: " + *why);
      return finish();
    }
    Descent descent;
    double kappa = options.kappa;
    for (const double k :
         options.kappa > 0 ? std::vector<double>{options.kappa} : std::vector<double>{2, 4, 8, 16, 32, 64}) {
      kappa = k;
      descent = descend(query, k);
      if (descent.status == PlanStatus::solved || descent.status == PlanStatus::not_found) break;
    }
    facts.set(NavigationFacts::kappa, kappa);
    report_descent(exact, std::move(descent), NavigationFacts::descent, query_options.record,
                   " (kappa " + std::to_string(kappa) + ")", report);
    return finish();
  }
};

// The disc round a box, its half-diagonal wide, grown by `grow`.
Sphere disc_round(const BoxGrid& box, double grow) {
  return {{(box.xmin + box.xmax) / 2, (box.ymin + box.ymax) / 2}, grow * box.diagonal() / 2};
}

OptionTable<NavigationFunctionOptions> navigation_options() {
  OptionTable<NavigationFunctionOptions> table;
  table
      .add("kappa", &NavigationFunctionOptions::kappa,
           "the navigation function's kappa (0: the smallest of 2, 4, ..., 64 that reaches the goal)", at_least(0))
      .add("step", &NavigationFunctionOptions::step, "the longest step (0: 1/200 of the world's diagonal)", at_least(0))
      .add("max-steps", &NavigationFunctionOptions::max_steps, "steps before the descent stops with status limit",
           at_least(1))
      .add("patience", &NavigationFunctionOptions::patience,
           "steps without getting closer to the goal before it is a local minimum", at_least(1));
  return table;
}

}  // namespace navigation_detail

using navigation_detail::SphereNavigation;

struct NavigationFunctionPlanner::Impl {
  ObstacleField field;
  SphereNavigation navigation;

  Impl(const CSpace& c, const NavigationFunctionOptions& o) : field(c) {
    const BoxGrid box = c.reference_box() && c.reference_box()->xmin <= c.reference_box()->xmax
                            ? BoxGrid{to_double(c.reference_box()->xmin), to_double(c.reference_box()->ymin),
                                      to_double(c.reference_box()->xmax), to_double(c.reference_box()->ymax), 1}
                            : box_around(c, 1);
    navigation.exact = descent_world(c);
    navigation.options = o;
    // The world's disc: round the box, or without bounds half as wide again round everything.
    navigation.world = navigation_detail::disc_round(box, c.world().bounds ? 1.0 : 1.5);
    for (const PolygonWithHoles& p : c.cobstacles())
      navigation.obstacles.push_back(navigation_detail::disc_around(p.outer));
    navigation.step = o.step > 0 ? o.step : box_around(c, 1).diagonal() / 200;
    navigation.clearance = [this](Vec2 q) { return field.clearance(q); };
  }
};

NavigationFunctionPlanner::NavigationFunctionPlanner(const CSpace& cspace, NavigationFunctionOptions options) {
  navigation_detail::check_options(options);
  impl_ = std::make_unique<Impl>(cspace, options);
}

NavigationFunctionPlanner::~NavigationFunctionPlanner() = default;

PlanReport<ExactPoint> NavigationFunctionPlanner::plan(const Query& query, const QueryOptions& options) {
  return impl_->navigation.plan(query, options);
}

PlannerEntry<TranslatingRobot> navigation_function_planner_entry() {
  return make_planner_entry<TranslatingRobot, NavigationFunctionOptions>(
      "navigation-function",
      "descent on Rimon and Koditschek's navigation function of the discs around the C-obstacles (sphere worlds)",
      navigation_detail::navigation_options(), [](const CSpace& cspace, const NavigationFunctionOptions& o) {
        return std::make_unique<NavigationFunctionPlanner>(cspace, o);
      });
}

struct RoundNavigationFunctionPlanner::Impl {
  SphereNavigation navigation;

  Impl(const RoundWorld& w, const NavigationFunctionOptions& o) {
    navigation.exact = descent_world(w);
    navigation.options = o;
    bool only_discs = true;  // whether every C-obstacle is a disc
    for (const RoundCore& core : w.cspace().obstacles) {
      if (core.kind != RoundCore::Kind::point) only_discs = false;
      else navigation.obstacles.push_back({approximate(core.points[0]), to_double(core.radius)});
    }
    if (const auto& disc = w.reference_disc()) {
      navigation.world = {{to_double(disc->center.x), to_double(disc->center.y)}, to_double(disc->radius)};
    } else if (const auto& b = w.reference_box()) {  // the course's sphere world in its box: the disc round it
      navigation.world = navigation_detail::disc_round(
          {to_double(b->xmin), to_double(b->ymin), to_double(b->xmax), to_double(b->ymax), 1}, 1.0);
    } else {
      navigation.not_spheres = "the world has no bounds (a sphere world's are a disc)";
    }
    if (!only_discs)
      navigation.not_spheres = w.cspace().robot == RoundCSpace::Robot::polygon
                                   ? "its robot is a polygon (whose C-obstacles of discs are rounded polygons)"
                                   : "it has walls or polygons besides its discs";
    const double diameter = 2 * navigation.world.radius;
    navigation.step = o.step > 0 ? o.step : (diameter > 0 ? diameter : 1) / 200;
    navigation.clearance = [this](Vec2 q) {
      const navigation_detail::Sphere& outer = navigation.world;
      double clear = outer.radius - std::hypot(q.x - outer.centre.x, q.y - outer.centre.y);
      for (const navigation_detail::Sphere& s : navigation.obstacles)
        clear = std::min(clear, std::hypot(q.x - s.centre.x, q.y - s.centre.y) - s.radius);
      return std::max(clear, 0.0);
    };
  }
};

RoundNavigationFunctionPlanner::RoundNavigationFunctionPlanner(const RoundWorld& world,
                                                               NavigationFunctionOptions options) {
  navigation_detail::check_options(options);
  impl_ = std::make_unique<Impl>(world, options);
}

RoundNavigationFunctionPlanner::~RoundNavigationFunctionPlanner() = default;

PlanReport<ExactPoint> RoundNavigationFunctionPlanner::plan(const Query& query, const QueryOptions& options) {
  return impl_->navigation.plan(query, options);
}

PlannerEntry<RoundRobot> round_navigation_function_planner_entry() {
  return make_planner_entry<RoundRobot, NavigationFunctionOptions>(
      "navigation-function",
      "descent on Rimon and Koditschek's navigation function of a sphere world's discs, exactly as given",
      navigation_detail::navigation_options(), [](const RoundWorld& world, const NavigationFunctionOptions& o) {
        return std::make_unique<RoundNavigationFunctionPlanner>(world, o);
      });
}

}  // namespace polyplan
