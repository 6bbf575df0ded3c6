#pragma once
// The JSON object `polyplan plan` and `polyplan arm` print for one query (docs/design.md "What the
// command-line program prints"), written from any planner's report:
//
//   {"query": "start/goal", "found": true, "length": 12.3456,
//    "path": [[x, y], ...], "path_exact": [["3/2", "7/10"], ...],      (points; arms: [[θ1, ...], ...]; poses below)
//    "certified": true, "certified_by": "exact path check (triangulation walk)",
//    "roadmap": {"kind": "visibility", "vertices": 120, ...}, "search": {...}, ...}
//
// `length` is null and `why_not` says why when nothing was found. Every fact of the report is a
// key; a dotted name nests ("roadmap.vertices" is roadmap → vertices).
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace polyplan {

// `query` is the query's name ("start/goal", "queries[2]", "easy"); left out when empty.
nlohmann::json plan_json(const PlanReport<ExactPoint>& report, const std::string& query = {});
nlohmann::json plan_json(const PlanReport<JointAngles>& report, const std::string& query = {});
// Poses: "path": [[x, y, theta], ...] (theta: the nominal angle in degrees, unwrapped along the
// path: consecutive entries differ by the turn between them), "path_exact":
// [["x", "y", "sin", "cos"], ...] (the exact rotation).
nlohmann::json plan_json(const PlanReport<Pose>& report, const std::string& query = {});
// A car's: "path": [[x, y, theta], ...] (theta in degrees, as the car turned: not wrapped), the
// poses at the segments' joints, and "segments": [{"steer": "L"|"S"|"R", "gear": 1|-1, "length",
// "start": [x, y, theta]}, ...] (as `polyplan steer` prints them, each with the pose it starts at).
nlohmann::json plan_json(const PlanReport<CarState>& report, const std::string& query = {});

// The facts alone, nested as in plan_json ({"roadmap": {"vertices": 120, ...}, ...}).
nlohmann::json facts_json(const Facts& facts);

// Where a fact nests in that JSON: "roadmap.vertices" is {"roadmap", "vertices"}.
std::vector<std::string> fact_json_keys(const std::string& name);

}  // namespace polyplan
