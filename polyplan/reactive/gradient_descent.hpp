#pragma once
// Gradient descent through the exact C-space, for the reactive planners (potential-field,
// navigation-function): each step goes along the descent direction a slope gives, at most `step`
// long, never longer than half the clearance where it starts nor than the way to the goal, halved
// where the descent turns sharply (the slope changes fast) and grown back by a quarter where it
// runs straight; every step's segment is checked exactly before it is taken, and halved until it
// passes. It ends
//   solved         within `tolerance` of the goal, the last step to the goal itself checked;
//   local_minimum  where the slope vanishes, the steps shrink to nothing, or `patience` steps in
//                  a row bring it no closer to the goal than it has been (it oscillates);
//   not_found      where the slope is undefined (in contact with an obstacle, say);
//   limit          after `max_steps` steps.
#include <polyplan/geometry/clearance.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/reactive/reactive_facts.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct Slope {
  Vec2 gradient;         // the descent goes against it
  double value = 0;      // of the function descended, for the facts
  double clearance = 0;  // the distance to the nearest obstacle there: half of it caps the step
};

// The slope at a point, or why there is none there.
struct SlopeAt {
  std::optional<Slope> slope;
  std::string why_none;
};
using SlopeFunction = std::function<SlopeAt(Vec2)>;

struct DescentOptions {
  double step = 1, tolerance = 1;
  std::size_t max_steps = 20000, patience = 400;
  double vanishing = 1e-12;  // a gradient shorter than this has vanished
};

struct Descent {
  std::vector<ExactPoint> path;  // start first, every step taken
  PlanStatus status = PlanStatus::limit;
  std::string why;
  Slope last;
};

// The exact tests a descent rests on: a polygon world's C-space (geometry/path_check.hpp), or a
// point or disc robot's world of discs and walls (geometry/round_world_check.hpp).
struct DescentWorld {
  std::function<PathCheck(const ExactPoint&, const ExactPoint&)> segment;
  std::function<PathCheck(const std::vector<ExactPoint>&)> path;
  std::function<std::optional<std::string>(const Query&)> query_not_free;
  // False when start and goal are proved apart (different components of the free space).
  std::function<bool(const ExactPoint&, const ExactPoint&)> may_join;
  std::string certificate;  // how a path's steps were proved free
};
// Each keeps a reference to its world, which must outlive it.
DescentWorld descent_world(const CSpace& cspace);
DescentWorld descent_world(const RoundWorld& world);

Descent descend(const DescentWorld& world, const Query& query, const SlopeFunction& slope,
                const DescentOptions& options);

// A query a descent need not be tried on, answered in `report` (true): a start or goal that is
// not free (invalid_query), or start and goal in different components of the free space (no_path,
// proved).
bool answered_before_descent(const DescentWorld& world, const Query& query, PlanReport<ExactPoint>& report);

// The descent as a planner's answer: the facts `keys` (its steps and where it stopped), its steps as
// the expanded configurations when `record`, and the path (certified: every step was checked
// exactly as it was taken, and the whole path again, whose bends the steps alone cannot judge at
// a pinch point) when solved, or the status and `why` (followed by `why_suffix`) otherwise —
// stopped_by "step limit" for a limit.
void report_descent(const DescentWorld& world, Descent descent, const DescentFacts& keys, bool record,
                    const std::string& why_suffix, PlanReport<ExactPoint>& report);

// "(x, y)" with six decimals.
std::string point_text(Vec2 p);

}  // namespace polyplan
