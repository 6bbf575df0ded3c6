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

  // A number as the file wrote it (floating-point literals arrive as their text).
  static std::string text(const json& v) { return detail::abbreviated_text(v.is_string() ? v.get<std::string>() : v.dump()); }

};

Arm read_arm(const ArmFileReader& r, const json& root) {
  Arm arm;
  if (!root.contains("links")) r.fail("arm", "missing field \"links\" (the link lengths, e.g. [1, 1])");
  arm.links = r.numbers(root["links"], "links", "a list of link lengths");
  if (arm.links.empty()) r.fail("links", "expected at least one link length, got []");
  for (std::size_t i = 0; i < arm.links.size(); ++i)
    if (!(arm.links[i] > 0))
      r.fail("links[" + std::to_string(i) + "]", "a link length must be positive, got " + ArmFileReader::text(root["links"][i]));
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
  return arm;
}

// Obstacle polygons are the world file's: handed to the world reader (exact numbers, simple
// polygons, holes inside, orientation), which names them "obstacles[i]" in the same file.
void read_obstacles(const json& root, const std::string& name, ArmProblem& problem, std::vector<std::string>& warnings) {
  if (!root.contains("obstacles")) return;
  const json obstacles_only = {{"obstacles", root["obstacles"]}};
  World world = parse_world(obstacles_only.dump(), name, &warnings);
  problem.obstacles = std::move(world.obstacles);
  problem.obstacle_names = std::move(world.obstacle_names);
}

void read_points(const ArmFileReader& r, const json& root, ArmProblem& problem) {
  if (!root.contains("points")) return;
  const json& points = root["points"];
  if (!points.is_array()) r.fail("points", "expected a list of points [[x, y], ...], got " + ArmFileReader::abbreviated(points));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string object = "points[" + std::to_string(i) + "]";
    const json& p = points[i];
    if (!p.is_array() || p.size() != 2) r.fail(object, "expected a point [x, y], got " + ArmFileReader::abbreviated(p));
    problem.points.emplace_back(r.number(p[0], object + "[0]"), r.number(p[1], object + "[1]"));
  }
}

void read_queries(const ArmFileReader& r, const json& root, ArmProblem& problem, std::vector<std::string>& warnings) {
  const std::size_t n = problem.arm.joints();
  if (root.contains("start") != root.contains("goal"))
    r.fail("arm", root.contains("start") ? "missing field \"goal\" (start is given)" : "missing field \"start\" (goal is given)");
  if (root.contains("start"))
    problem.queries.push_back({"start/goal", r.angles(root["start"], "start", n), r.angles(root["goal"], "goal", n)});
  if (!root.contains("queries")) return;
  const json& queries = root["queries"];
  if (!queries.is_array()) r.fail("queries", "expected a list of {\"name\", \"start\", \"goal\"}");
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const std::string object = "queries[" + std::to_string(i) + "]";
    const json& q = queries[i];
    if (!q.is_object()) r.fail(object, "expected {\"name\": \"...\", \"start\": [θ1, ...], \"goal\": [θ1, ...]}");
    r.warn_unknown(q, object, {"name", "start", "goal"}, &warnings);
    ArmQuery query;
    query.name = object;
    if (q.contains("name")) {
      if (!q["name"].is_string() || q["name"].get<std::string>().empty())
        r.fail(object + ".name", "expected a non-empty string, got " + ArmFileReader::abbreviated(q["name"]));
      query.name = q["name"].get<std::string>();
    }
    for (const char* key : {"start", "goal"})
      if (!q.contains(key)) r.fail(object, std::string("missing field \"") + key + "\"");
    query.start = r.angles(q["start"], object + ".start", n);
    query.goal = r.angles(q["goal"], object + ".goal", n);
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
  r.warn_unknown(root, "arm", {"links", "link_width", "self_collision", "obstacles", "points", "start", "goal", "queries"},
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
