#pragma once
// What the car's planners (hybrid-astar, car-rrt) share, so that each writes only its search: the
// world's car (its certified collision checks and its steering curves: Dubins forward only,
// Reeds–Shepp with reverse), the query's poses and their check — and, when the reference point lies
// in the body, a proof of no path where start and goal lie in different components of a point's
// free space (status no_path) — and one report for every path:
// each segment certified again from scratch before it is returned, its length, gear changes and
// the facts
//   gear_changes    how often the car changes between forward and reverse
//   certification.enclosures   swept-body enclosures tested during the query (search and re-check)
//   query_seconds
#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/car_motion.hpp>
#include <polyplan/car/car_query.hpp>
#include <polyplan/car/holonomic_distance.hpp>
#include <polyplan/car/steering_path.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

class CarPlanner : public Planner<SteeredCar> {
 public:
  PlanReport<CarState> plan(const Query& query, const QueryOptions& options = {}) final;

 protected:
  // The world (which must outlive the planner) must have a car: std::invalid_argument otherwise.
  explicit CarPlanner(const World& world);

  // What search() returns: a path from the start (its first entry, arriving by no segment) whose
  // every entry is reached from the one before by its `arrival`, certified; ending at the goal
  // pose (or, for a goal region, where `reached_goal` says); or the failure and why.
  struct Attempt {
    std::vector<CarState> path;
    PlanStatus failure = PlanStatus::not_found;
    std::string why_not;
    std::shared_ptr<const PlanGraph<CarState>> graph;
  };
  virtual Attempt search(const CarPose& start, const CarPose& goal, Facts& facts, bool record) = 0;
  // Whether a path may end at `end`, not exactly at the goal: a goal region's planner says yes
  // within its tolerance. Exactly (to rounding) at the goal by default.
  virtual bool reaches_goal(const CarPose& end, const CarPose& goal) const;

  // Seconds since plan() was entered: what a search holds to its time limit, so that the query's
  // checks and the holonomic distance to the goal count against it too.
  double query_seconds() const { return query_clock_.seconds(); }
  const CarCollision& collision() const { return collision_; }
  // The shortest path of a point among the obstacles to the query's goal (set before search()),
  // when the reference point lies in the body (car/holonomic_distance.hpp); null otherwise.
  const HolonomicDistance* holonomic() const { return holonomic_ ? &*holonomic_ : nullptr; }
  const World& world() const { return world_; }
  double radius() const { return collision_.turning_radius(); }
  bool reverse() const { return collision_.reverse(); }
  // The car's shortest curve ignoring obstacles (Reeds–Shepp when it may reverse, else Dubins)
  // and its length: a lower bound on any path's length between the poses.
  SteeringPath steering_path(const CarPose& from, const CarPose& to) const {
    return shortest_car_path(*world_.robot.car, from, to);
  }
  double steering_distance(const CarPose& from, const CarPose& to) const {
    return car_distance(*world_.robot.car, from, to);
  }
  // car/car_motion.hpp's, on this car.
  std::optional<std::vector<CarState>> certified_states(const CarPose& from, const SteeringPath& path,
                                                        const CarPose& to) const {
    return polyplan::certified_states(collision_, from, path, to);
  }

 private:
  const World& world_;
  CarCollision collision_;
  std::optional<HolonomicDistance> holonomic_;
  Stopwatch query_clock_;
};

}  // namespace polyplan
