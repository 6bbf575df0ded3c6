#pragma once
// The navigation function of a sphere world (Rimon & Koditschek 1992; Choset et al. 4.6),
// registered as `navigation-function`: φ = γ / (γ^κ + β)^(1/κ), γ = |q − goal|², β the product of
// β₀ = r₀² − |q − c₀|² (the world's disc) and βᵢ = |q − cᵢ|² − rᵢ² (the obstacles' discs). For κ
// large enough it has one minimum, the goal, and no other local minimum in the free space.
//
// polyplan's worlds are polygons: each C-obstacle stands for the disc around it — centre its
// vertices' centroid, radius the farthest vertex (a fine regular polygon gives its own circle back) —
// and the world's disc is the one around the reference box (or around everything, without bounds).
// A world whose discs overlap, or leave the world's disc, is not a sphere world: not_found, saying
// which. The descent follows −∇φ, whose direction is that of −(β∇γ − (γ/κ)∇β) — computed as
// −(∇γ − (γ/κ) Σ ∇βᵢ/βᵢ), with no power of κ, so a large κ cannot underflow (the known trouble of
// φ itself) — through the exact C-space (reactive/gradient_descent.hpp). With `kappa` 0 it tries
// κ = 2, 4, ..., 64 until one reaches the goal, and reports the κ it used (navigation.kappa).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>

namespace polyplan {

struct NavigationFunctionOptions {
  double kappa = 0;  // 0: the smallest of 2, 4, ..., 64 that reaches the goal
  double step = 0;   // 0: 1/200 of the diagonal of the box around the world
  std::size_t max_steps = 20000, patience = 400;
};

class NavigationFunctionPlanner final : public Planner<TranslatingRobot> {
 public:
  // `cspace` must outlive the planner. Throws std::invalid_argument for a κ below 1 (other than
  // 0) or not finite, a negative step, 0 patience.
  NavigationFunctionPlanner(const CSpace& cspace, NavigationFunctionOptions options = {});
  ~NavigationFunctionPlanner() override;
  // Facts: roadmap.kind, navigation.kappa, navigation.spheres, navigation.steps, navigation.stopped_at.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<TranslatingRobot> navigation_function_planner_entry();

// The same on a world of discs, for a point or disc robot (RoundRobot): the obstacles' discs are
// the world's discs exactly (grown by the robot's radius), the world's disc its disc bounds
// (shrunk alike) or the disc round its box bounds; walls, polygons or no bounds make it no sphere
// world (not_found, saying so). Every step is checked exactly among the discs
// (geometry/round_world_check.hpp).
class RoundNavigationFunctionPlanner final : public Planner<RoundRobot> {
 public:
  // `world` must outlive the planner; the options as above.
  RoundNavigationFunctionPlanner(const RoundWorld& world, NavigationFunctionOptions options = {});
  ~RoundNavigationFunctionPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<RoundRobot> round_navigation_function_planner_entry();

}  // namespace polyplan
