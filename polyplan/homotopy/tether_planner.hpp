#pragma once
// A tethered robot (the course's sampling-planner homework, part 3), registered as `tether`: a tether anchored at
// `tether-base` (X,Y; default the query's start) stays taut, so it is the shortest path from the base to the robot in
// its homotopy class, and may never be longer than `tether-length` L (0: no bound). A configuration is the robot's
// position and the tether's word (homotopy/h_signature.hpp).
//
// As the seed's algorithm: a Dijkstra over (visibility-graph vertex, word) from the base, bounded
// by L, gives every (vertex, class) the tether reaches and its taut length (G_w, the fact
// tether.reachable counts them); then a Dijkstra of the robot over (vertex, tether word) from the
// start, with the tether it starts with (straight from the base when that is free, else the
// shortest), admitting only states whose tether is within L. Along a straight motion the taut
// tether's length is a convex function of the robot's place (geodesic distance in the universal
// cover, simply connected: Pollack, Sharir & Rote), so it is largest at an end: checking the
// vertices checks the motion. Equal to L is allowed: the tether's lengths, sums of square roots,
// are compared with L exactly (geometry/root_sum.hpp), so a tether 0.85 + 0.85 long fits L = 1.7.
//
// Facts: tether {word, length, largest (along the path), at_goal (the taut tether at the goal,
// "(x, y) ..." exact), reachable, classes (with list-classes: every class the goal is reached in
// within L, with its tether length)}. No class within L: no_path. The picture: the rays, the base,
// and the taut tether at the path's vertices.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace polyplan {

struct TetherOptions {
  std::string tether_base;     // "X,Y"; empty: the query's start
  Rational tether_length = 0;  // L, exact as written ("1.7" is 17/10); 0: no bound
  bool list_classes = false;
  std::size_t max_states = 1000000;
};

class TetherPlanner final : public Planner<TranslatingRobot> {
 public:
  // `cspace` must outlive the planner. Throws std::invalid_argument for a bad option.
  TetherPlanner(const CSpace& cspace, TetherOptions options = {});
  ~TetherPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<TranslatingRobot> tether_planner_entry();

}  // namespace polyplan
