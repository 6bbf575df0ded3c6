#include <polyplan/reactive/gradient_descent.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/round_query.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/plan/plan_facts.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan {
namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// One step from `at` along `direction`, at most `length` long: halved until its segment is
// exactly free (a step that started in the free space always ends so, at some length).
std::optional<ExactPoint> free_step(const DescentWorld& world, const ExactPoint& at, Vec2 from, Vec2 direction,
                                    double length) {
  for (int halvings = 0; halvings < 60; ++halvings, length /= 2) {
    const ExactPoint to = exactly({from.x + length * direction.x, from.y + length * direction.y});
    if (world.segment(at, to).valid) return to;
  }
  return std::nullopt;
}

Descent& stop(Descent& d, Vec2 q, const std::string& why) {
  d.status = PlanStatus::local_minimum;
  d.why = "a local minimum at " + point_text(q) + ": " + why;
  return d;
}

}  // namespace

std::string point_text(Vec2 p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

DescentWorld descent_world(const CSpace& cspace) {
  return {[&cspace](const ExactPoint& a, const ExactPoint& b) { return check_segment(cspace, a, b); },
          [&cspace](const std::vector<ExactPoint>& path) { return check_path(cspace, path); },
          [&cspace](const Query& query) { return cspace.query_not_free(query); },
          [&cspace](const ExactPoint& a, const ExactPoint& b) { return share_a_component(cspace, a, b); },
          "exact segment test of every step as it was taken, and of the whole path (arrangement zone walk)"};
}

DescentWorld descent_world(const RoundWorld& world) {
  return {[&world](const ExactPoint& a, const ExactPoint& b) { return world.check_segment(a, b); },
          [&world](const std::vector<ExactPoint>& path) { return world.check_path(path); },
          [&world](const Query& query) { return query_not_free(world, query); },
          [](const ExactPoint&, const ExactPoint&) { return true; },  // no components known: none proved apart
          "exact rational segment test of every step as it was taken, and of the whole path"};
}

Descent descend(const DescentWorld& world, const Query& query, const SlopeFunction& slope, const DescentOptions& o) {
  Descent d;
  d.path = {query.start};
  const Vec2 goal = approximate(query.goal);
  Vec2 q = approximate(query.start), previous_direction{0, 0};
  double current = o.step, best = distance(q, goal);
  std::size_t since_best = 0;
  for (std::size_t k = 0; k < o.max_steps; ++k) {
    if (distance(q, goal) <= o.tolerance) {
      if (world.segment(d.path.back(), query.goal).valid) {
        d.path.push_back(query.goal);
        d.status = PlanStatus::solved;
      } else {
        d.status = PlanStatus::not_found;
        d.why = "within the goal tolerance at " + point_text(q) + ", but the straight step to the goal is not free";
      }
      return d;
    }
    const SlopeAt here = slope(q);
    if (!here.slope) {
      d.status = PlanStatus::not_found;
      d.why = "at " + point_text(q) + " " + here.why_none;
      return d;
    }
    d.last = *here.slope;
    const double g = std::hypot(d.last.gradient.x, d.last.gradient.y);
    if (!(g > o.vanishing)) return stop(d, q, "the gradient vanishes");
    const Vec2 direction{-d.last.gradient.x / g, -d.last.gradient.y / g};
    // A sharp turn means the slope changes fast here: shorter steps; a straight run, longer.
    const bool sharp = k > 0 && direction.x * previous_direction.x + direction.y * previous_direction.y < 0.5;
    current = sharp ? current / 2 : std::min(o.step, current * 1.25);
    previous_direction = direction;
    if (current < 1e-9 * o.step) return stop(d, q, "its steps shrank to nothing");
    const double length = std::min({current, distance(q, goal), d.last.clearance / 2});
    const auto to = free_step(world, d.path.back(), q, direction, length);
    if (!to) return stop(d, q, "no step along the gradient is free");
    d.path.push_back(*to);
    q = approximate(*to);
    if (distance(q, goal) < best * (1 - 1e-9)) {
      best = distance(q, goal);
      since_best = 0;
    } else if (++since_best >= o.patience) {
      return stop(d, q, std::to_string(o.patience) + " steps brought it no closer to the goal (it oscillates)");
    }
  }
  d.why = "the step limit (" + std::to_string(o.max_steps) + ") ended the descent at " + point_text(q);
  return d;
}

bool answered_before_descent(const DescentWorld& world, const Query& query, PlanReport<ExactPoint>& report) {
  if (auto why = world.query_not_free(query)) {
    report.fail(PlanStatus::invalid_query, *why);
    return true;
  }
  if (!world.may_join(query.start, query.goal)) {
    report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
    return true;
  }
  return false;
}

void report_descent(const DescentWorld& world, Descent descent, const DescentFacts& keys, bool record,
                    const std::string& why_suffix, PlanReport<ExactPoint>& report) {
  if (record) report.recording.expanded = descent.path;  // the picture shows the descent, wherever it stopped
  report.facts.set(keys.steps, descent.path.size() - 1);
  const Vec2 end = approximate(descent.path.back());
  report.facts.set(keys.stopped_at, FactPoint{end.x, end.y});
  // Each step was tested as it was taken; the whole path is tested again, found or not, so that a
  // mistake is an answer that says so, never a path through an obstacle.
  const PathCheck whole = world.path(descent.path);
  if (whole.valid) report.path = std::move(descent.path);
  if (descent.status != PlanStatus::solved) {
    if (descent.status == PlanStatus::limit) report.facts.set(QueryFacts::stopped_by, "step limit");
    report.fail(descent.status, descent.why + why_suffix);
    return;
  }
  if (!whole.valid) {
    report.fail(PlanStatus::not_found, "the descent's path is not a valid motion: " + whole.reason);
    return;
  }
  report.succeed();
  report.length = euclidean_length(report.path);
  report.certificate = {true, world.certificate};
}

}  // namespace polyplan
