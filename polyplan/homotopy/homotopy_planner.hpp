#pragma once
// The K shortest paths from start to goal of K distinct homotopy classes, registered as
// `homotopy`: a Dijkstra over (visibility-graph vertex, reduced word) (homotopy/class_graph.hpp)
// that records the goal each time it is settled in a class not met before. Each path is the
// shortest (so taut) path of its class, found in order of length. The report's path is the
// shortest; PlanReport::paths holds all K, each with its fact `word` ("t1 t2'" as
// homotopy/h_signature.hpp spells it). Fewer than K when fewer exist within `max-length` (0: no
// bound) or the search makes `max-states` states (then stopped_by says so).
//
// Facts: homotopy.classes (found), homotopy.word (the shortest's), homotopy.states,
// homotopy.rays (the holes of the free space, one letter each).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>

namespace polyplan {

struct HomotopyOptions {
  std::size_t classes = 4;
  Rational max_length = 0;  // exact as written, compared with the paths' lengths exactly; 0: none
  std::size_t max_states = 1000000;
};

class HomotopyPlanner final : public Planner<TranslatingRobot> {
 public:
  // `cspace` must outlive the planner.
  HomotopyPlanner(const CSpace& cspace, HomotopyOptions options = {});
  ~HomotopyPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<TranslatingRobot> homotopy_planner_entry();

}  // namespace polyplan
