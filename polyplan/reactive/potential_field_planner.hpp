#pragma once
// The potential-field planner (`potential-field`; Choset et al. ch. 4): gradient descent on the
// goal's attraction plus each C-obstacle's and wall's repulsion (reactive/obstacle_field.hpp).
//
// The descent and its ends (solved, local_minimum, not_found, limit) are
// reactive/gradient_descent.hpp's; no_path when start and goal lie in different components of the
// free space (proved).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/reactive/obstacle_field.hpp>

#include <cstddef>
#include <memory>

namespace polyplan {

struct PotentialFieldOptions {
  double zeta = 1, d_star = 0, eta = 1, q_star = 1;
  double step = 0;            // the longest step; 0: 1/200 of the diagonal of the box around the world (box_around)
  double goal_tolerance = 0;  // 0: the step
  std::size_t max_steps = 20000;
  std::size_t patience = 400;  // steps without getting closer to the goal before it is a local minimum
};

class PotentialFieldPlanner final : public Planner<TranslatingRobot> {
 public:
  // `cspace` must outlive the planner. Throws std::invalid_argument for a weight or an influence
  // that is negative or not finite, a negative step or tolerance, or 0 patience.
  PotentialFieldPlanner(const CSpace& cspace, PotentialFieldOptions options = {});
  ~PotentialFieldPlanner() override;

  // Facts: roadmap.kind "potential-field", potential.steps, potential.step (the longest),
  // potential.stopped_at ("(x, y)"), potential.gradient (its length there), potential.value,
  // query_seconds. With QueryOptions::record the picture's cells hold log(1 + U) on a 64 × 64
  // grid of the box around the world (reactive/potential_map.hpp), and its expanded points are the
  // descent's steps, wherever it stopped.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<TranslatingRobot> potential_field_planner_entry();

// The same for a point or disc robot among discs, walls and polygons (RoundRobot): each obstacle
// repels from the exact distance the robot keeps from it (reactive/round_obstacle_field.hpp), and
// every step is checked exactly among them (geometry/round_world_check.hpp). No components are
// known there, so no query is answered no_path before the descent. The step's default is 1/200 of
// the diagonal of the box around the world (box_around of a RoundWorld); facts and options as above.
class RoundPotentialFieldPlanner final : public Planner<RoundRobot> {
 public:
  // `world` must outlive the planner; throws as PotentialFieldPlanner does.
  RoundPotentialFieldPlanner(const RoundWorld& world, PotentialFieldOptions options = {});
  ~RoundPotentialFieldPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<RoundRobot> round_potential_field_planner_entry();

}  // namespace polyplan
