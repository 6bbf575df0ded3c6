#include <polyplan/io/arm_reader.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/detail/exact_json.hpp>
#include <polyplan/io/world_reader.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <set>

namespace polyplan {
namespace {

using json = nlohmann::json;

// The file name for messages, and the checks every field shares.
class ArmFileReader : public detail::JsonFileReader {
 public:
  using JsonFileReader::JsonFileReader;

  // Arm numbers are doubles by nature (they feed cos and sin), but they are read from their text
  // like every number of polyplan's files, and rounded once, to the nearest double.
  double number(const json& v, const std::string& object) const {
    if (!v.is_number_integer() && !v.is_string()) fail(object, "not a number: " + abbreviated(v));
    const std::string text = v.is_string() ? v.get<std::string>() : v.dump();
    std::string why;
    const auto exact = parse_rational(text, &why);
    if (!exact) fail(object, why + ": " + abbreviated(v));
    const double value = to_double(*exact);
    return value;
  }

  std::vector<double> numbers(const json& v, const std::string& object, const std::string& expected) const {
    if (!v.is_array()) fail(object, "expected " + expected + ", got " + abbreviated(v));
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], object + "[" + std::to_string(i) + "]"));
    return out;
  }

  JointAngles angles(const json& v, const std::string& object, std::size_t links) const {
    const std::string expected = std::to_string(links) + " joint angles (one per link, radians)";
    JointAngles a = numbers(v, object, "a list of " + expected);
    if (a.size() != links) fail(object, "expected " + expected + ", got " + std::to_string(a.size()));
    return a;
  }

  // The number exactly as written; number() has accepted it.
  static Rational exact(const json& v) { return *parse_rational(v.is_string() ? v.get<std::string>() : v.dump()); }

  Eigen::Vector2d point(const json& p, const std::string& object) const {
    if (!p.is_array() || p.size() != 2) fail(object, "expected a point [x, y], got " + abbreviated(p));
    return {number(p[0], object + "[0]"), number(p[1], object + "[1]")};
  }

  // A number as the file wrote it (floating-point literals arrive as their text).
  static std::string text(const json& v) {
    return detail::abbreviated_text(v.is_string() ? v.get<std::string>() : v.dump());
  }
};

// "limits": [[lo, hi], ...], one pair per joint, radians.
std::vector<std::pair<double, double>> read_limits(const ArmFileReader& r, const json& v, std::size_t joints) {
  const std::string expected = std::to_string(joints) + " joint limits [lo, hi] (one per link, radians)";
  if (!v.is_array()) r.fail("limits", "expected a list of " + expected + ", got " + ArmFileReader::abbreviated(v));
  if (v.size() != joints) r.fail("limits", "expected " + expected + ", got " + std::to_string(v.size()));
  std::vector<std::pair<double, double>> limits;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string object = "limits[" + std::to_string(i) + "]";
    const std::vector<double> pair = r.numbers(v[i], object, "[lo, hi] (radians)");
    if (pair.size() != 2) r.fail(object, "expected [lo, hi] (radians), got " + ArmFileReader::abbreviated(v[i]));
    if (pair[0] > pair[1])
      r.fail(object, "lo " + ArmFileReader::text(v[i][0]) + " is above hi " + ArmFileReader::text(v[i][1]) +
                         " (radians, [lo, hi])");
    limits.emplace_back(pair[0], pair[1]);
  }
  return limits;
}

Arm read_arm(const ArmFileReader& r, const json& root) {
  Arm arm;
  if (!root.contains("links")) r.fail("arm", "missing field \"links\" (the link lengths, e.g. [1, 1])");
  arm.links = r.numbers(root["links"], "links", "a list of link lengths");
  if (arm.links.empty()) r.fail("links", "expected at least one link length, got []");
  for (const json& l : root["links"]) arm.exact_links.push_back(ArmFileReader::exact(l));
  for (std::size_t i = 0; i < arm.links.size(); ++i)
    if (!(arm.links[i] > 0))
      r.fail("links[" + std::to_string(i) + "]",
             "a link length must be positive, got " + ArmFileReader::text(root["links"][i]));
  if (root.contains("link_width")) {
    arm.link_width = r.number(root["link_width"], "link_width");
    if (arm.link_width < 0)
      r.fail("link_width", "must be 0 (segments) or positive, got " + ArmFileReader::text(root["link_width"]));
  }
  if (!std::isfinite(arm.reach())) r.fail("links", "the arm's total length is not a finite double");
  if (root.contains("self_collision")) {
    if (!root["self_collision"].is_boolean())
      r.fail("self_collision", "expected true or false, got " + ArmFileReader::abbreviated(root["self_collision"]));
    arm.self_collision = root["self_collision"].get<bool>();
  }
  if (root.contains("limits")) arm.limits = read_limits(r, root["limits"], arm.joints());
  return arm;
}

// Obstacle polygons are the world file's: handed to the world reader (exact numbers, simple
// polygons, holes inside, orientation), which names them "obstacles[i]" in the same file.
void read_obstacles(const json& root, const std::string& name, ArmProblem& problem,
                    std::vector<std::string>& warnings) {
  if (!root.contains("obstacles")) return;
  const json obstacles_only = {{"obstacles", root["obstacles"]}};
  World world = parse_world(obstacles_only.dump(), name, &warnings);
  problem.obstacles = std::move(world.obstacles);
  problem.obstacle_names = std::move(world.obstacle_names);
}

void read_points(const ArmFileReader& r, const json& root, ArmProblem& problem) {
  if (!root.contains("points")) return;
  const json& points = root["points"];
  if (!points.is_array())
    r.fail("points", "expected a list of points [[x, y], ...], got " + ArmFileReader::abbreviated(points));
  for (std::size_t i = 0; i < points.size(); ++i)
    problem.points.push_back(r.point(points[i], "points[" + std::to_string(i) + "]"));
}

// A query's goal in `q` (the file's top level, or one of its queries): joint angles ("goal") or the
// hand at a point ("goal_point", with "goal_orientation" optionally), exactly one of them. `where`
// names the query ("arm" at the top level), `prefix` its fields ("" or "queries[2].").
void read_goal(const ArmFileReader& r, const json& q, const std::string& where, const std::string& prefix,
               std::size_t joints, ArmQuery& query) {
  const bool angles = q.contains("goal"), point = q.contains("goal_point");
  if (angles && point)
    r.fail(where,
           "both \"goal\" and \"goal_point\" given: a query's goal is joint angles or the hand at a point, not both");
  if (!angles && !point) r.fail(where, "missing field \"goal\" (or \"goal_point\")");
  if (q.contains("goal_orientation") && !point)
    r.fail(prefix + "goal_orientation", "given without \"goal_point\" (it is the hand's orientation at that point)");
  if (angles) {
    query.goal = r.angles(q["goal"], prefix + "goal", joints);
    return;
  }
  const json& p = q["goal_point"];
  WorkspaceGoal goal{r.point(p, prefix + "goal_point"), std::nullopt,
                     ExactPoint{ArmFileReader::exact(p[0]), ArmFileReader::exact(p[1])}};
  if (q.contains("goal_orientation")) goal.orientation = r.number(q["goal_orientation"], prefix + "goal_orientation");
  query.goal_point = goal;
}

void read_queries(const ArmFileReader& r, const json& root, ArmProblem& problem, std::vector<std::string>& warnings) {
  const std::size_t n = problem.arm.joints();
  const bool goal_given = root.contains("goal") || root.contains("goal_point");
  if (root.contains("start") != goal_given)
    r.fail("arm", root.contains("start") ? "missing field \"goal\" or \"goal_point\" (start is given)"
                                         : std::string("missing field \"start\" (") +
                                               (root.contains("goal") ? "goal" : "goal_point") + " is given)");
  if (root.contains("start")) {
    ArmQuery query{"start/goal", r.angles(root["start"], "start", n), {}};
    read_goal(r, root, "arm", "", n, query);
    problem.queries.push_back(std::move(query));
  } else if (root.contains("goal_orientation")) {
    r.fail("goal_orientation", "given without \"goal_point\" (it is the hand's orientation at that point)");
  }
  if (!root.contains("queries")) return;
  const json& queries = root["queries"];
  if (!queries.is_array()) r.fail("queries", "expected a list of {\"name\", \"start\", \"goal\"}");
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const std::string object = "queries[" + std::to_string(i) + "]";
    const json& q = queries[i];
    if (!q.is_object()) r.fail(object, "expected {\"name\": \"...\", \"start\": [θ1, ...], \"goal\": [θ1, ...]}");
    r.warn_unknown(q, object, {"name", "start", "goal", "goal_point", "goal_orientation"}, &warnings);
    ArmQuery query;
    query.name = object;
    if (q.contains("name")) {
      if (!q["name"].is_string() || q["name"].get<std::string>().empty())
        r.fail(object + ".name", "expected a non-empty string, got " + ArmFileReader::abbreviated(q["name"]));
      query.name = q["name"].get<std::string>();
    }
    if (!q.contains("start")) r.fail(object, "missing field \"start\"");
    query.start = r.angles(q["start"], object + ".start", n);
    read_goal(r, q, object, object + ".", n, query);
    // Programs select queries by name: a repeated name would make the choice silent.
    for (const ArmQuery& earlier : problem.queries)
      if (earlier.name == query.name) r.fail(object + ".name", "the query name \"" + query.name + "\" is used twice");
    problem.queries.push_back(std::move(query));
  }
}

}  // namespace

ArmProblem parse_arm_problem(const std::string& text, const std::string& name, std::vector<std::string>* warnings) {
  const ArmFileReader r(name);
  const json root = r.parse(text);
  if (!root.is_object()) r.fail("arm", "expected a JSON object at the top level");

  std::vector<std::string> found_warnings;
  r.warn_unknown(root, "arm",
                 {"links", "link_width", "self_collision", "limits", "obstacles", "points", "start", "goal",
                  "goal_point", "goal_orientation", "queries"},
                 &found_warnings);

  ArmProblem problem;
  problem.source = name;
  problem.arm = read_arm(r, root);
  read_obstacles(root, name, problem, found_warnings);
  read_points(r, root, problem);
  read_queries(r, root, problem, found_warnings);

  if (warnings) warnings->insert(warnings->end(), found_warnings.begin(), found_warnings.end());
  else
    for (const auto& w : found_warnings) std::cerr << "warning: " << w << '\n';
  return problem;
}

ArmProblem read_arm_problem(const std::string& path, std::vector<std::string>* warnings) {
  return parse_arm_problem(detail::read_text_file(path), path, warnings);
}

}  // namespace polyplan
