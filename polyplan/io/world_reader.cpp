#include <polyplan/io/world_reader.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/geometry/world_validation.hpp>
#include <polyplan/io/detail/exact_json.hpp>
#include <polyplan/io/wkt_reader.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>

namespace polyplan {
namespace {

using json = nlohmann::json;

// Reading context: the file name and a path of keys, so every message names the object.
class Reader : public detail::JsonFileReader {
 public:
  using JsonFileReader::JsonFileReader;

  Rational number(const json& v, const std::string& object) const {
    std::string text;
    if (v.is_number_integer())
      return v.is_number_unsigned() ? Rational(mpz_class(std::to_string(v.get<std::uint64_t>())))
                                    : Rational(mpz_class(std::to_string(v.get<std::int64_t>())));
    if (!v.is_string()) fail(object, "not a number: " + abbreviated(v));
    std::string why;
    auto value = parse_rational(v.get<std::string>(), &why);
    if (!value) fail(object, why + ": " + abbreviated(v));
    return *value;
  }

  ExactPoint point(const json& v, const std::string& object) const {
    if (!v.is_array() || v.size() < 2) fail(object, "expected a point [x, y], got " + abbreviated(v));
    if (v.size() != 2) fail(object, "expected a point [x, y], got " + abbreviated(v));
    return {number(v[0], object + "[0]"), number(v[1], object + "[1]")};
  }

  // A start or goal: [x, y], or [x, y, theta] with theta in degrees (a rotating robot).
  void pose(const json& v, const std::string& object, ExactPoint& position, std::optional<double>& theta) const {
    if (!v.is_array() || v.size() < 2 || v.size() > 3)
      fail(object, "expected a point [x, y] or a pose [x, y, theta] (theta in degrees), got " + abbreviated(v));
    position = {number(v[0], object + "[0]"), number(v[1], object + "[1]")};
    if (v.size() == 3) {
      const Rational degrees = number(v[2], object + "[2] (theta, degrees)");
      if (abs(degrees) > 1e6)
        fail(object + "[2]", "theta " + to_string(degrees) + " degrees: expected an angle within ±1e6 degrees");
      theta = to_double(degrees);
    }
  }

  // "car": {"turning_radius": R, "reverse": true|false}.
  CarSteering car(const json& v, std::vector<std::string>* warnings) const {
    if (!v.is_object())
      fail("robot.car", "expected {\"turning_radius\": R, \"reverse\": true|false}, got " + abbreviated(v));
    warn_unknown(v, "robot.car", {"turning_radius", "reverse"}, warnings);
    CarSteering car;
    const Rational radius = number(required(v, "turning_radius", "robot.car"), "robot.car.turning_radius");
    car.turning_radius = to_double(radius);
    if (radius <= 0 || !std::isfinite(car.turning_radius) || car.turning_radius <= 0)
      fail("robot.car.turning_radius", to_string(radius) + ": expected a positive number");
    if (v.contains("reverse")) {
      if (!v["reverse"].is_boolean())
        fail("robot.car.reverse", "expected true or false, got " + abbreviated(v["reverse"]));
      car.reverse = v["reverse"].get<bool>();
    }
    return car;
  }

  Query query(const json& start, const json& goal, const std::string& start_object, const std::string& goal_object,
              std::string name, bool car) const {
    Query q;
    pose(start, start_object, q.start, q.start_theta);
    pose(goal, goal_object, q.goal, q.goal_theta);
    // A car's heading is half its pose: a start without one is a mistake, not heading 0.
    if (car && !q.start_theta)
      fail(start_object, "a car's pose is [x, y, theta] (theta in degrees), got " + abbreviated(start));
    if (car && !q.goal_theta)
      fail(goal_object, "a car's pose is [x, y, theta] (theta in degrees), got " + abbreviated(goal));
    q.name = std::move(name);
    return q;
  }

  Ring ring(const json& v, const std::string& object) const {
    if (!v.is_array()) fail(object, "expected a list of points [[x, y], ...], got " + abbreviated(v));
    Ring r;
    r.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) r.push_back(point(v[i], object + "[" + std::to_string(i) + "]"));
    return r;
  }

  PolygonWithHoles polygon(const json& v, const std::string& object, std::vector<std::string>* warnings) const {
    if (v.is_array()) return {ring(v, object), {}};
    if (!v.is_object())
      fail(object, "expected a polygon (a list of points or {\"outer\", \"holes\"}), got " + abbreviated(v));
    warn_unknown(v, object, {"outer", "holes"}, warnings);
    PolygonWithHoles p;
    p.outer = ring(required(v, "outer", object), object + ".outer");
    if (v.contains("holes")) {
      const json& holes = v["holes"];
      if (!holes.is_array()) fail(object + ".holes", "expected a list of rings");
      for (std::size_t i = 0; i < holes.size(); ++i)
        p.holes.push_back(ring(holes[i], object + ".holes[" + std::to_string(i) + "]"));
    }
    return p;
  }

  // {"after_moves": k, "add_obstacle": polygon} or {"after_moves": k, "remove_obstacle": i}.
  WorldChange change(const json& v, const std::string& object, std::vector<std::string>* warnings) const {
    const std::string form =
        "expected {\"after_moves\": k, \"add_obstacle\": [[x, y], ...]} or {\"after_moves\": k, \"remove_obstacle\": "
        "i}";
    if (!v.is_object()) fail(object, form + ", got " + abbreviated(v));
    warn_unknown(v, object, {"after_moves", "add_obstacle", "remove_obstacle"}, warnings);
    WorldChange c;
    c.name = object;
    c.after_moves = count(required(v, "after_moves", object), object + ".after_moves");
    if (v.contains("add_obstacle") == v.contains("remove_obstacle"))
      fail(object, "give one of \"add_obstacle\" and \"remove_obstacle\": " + form);
    if (v.contains("add_obstacle")) c.added = polygon(v["add_obstacle"], object + ".add_obstacle", warnings);
    else c.removed = count(v["remove_obstacle"], object + ".remove_obstacle");
    return c;
  }

  // A world's top level says what is free: an unknown key holding a list or an object (it may
  // describe obstacles this reader does not know) is an error, not a warning; a scalar one (a name,
  // a colour) is a warning.
  void refuse_unknown_shapes(const json& root, std::vector<std::string>* warnings) const {
    static const std::set<std::string> known{"bounds", "obstacles", "obstacles_wkt", "robot", "start",
                                             "goal",   "queries",   "changes",       "discs", "walls"};
    for (const auto& item : root.items())
      if (!known.count(item.key()) && (item.value().is_array() || item.value().is_object()))
        fail("world", "unknown field \"" + detail::abbreviated_text(item.key()) +
                          "\": it may describe what is not free, and is not read (a world's fields: bounds, "
                          "obstacles, obstacles_wkt, discs, walls, robot, start, goal, queries, changes)");
    warn_unknown(root, "world", known, warnings);
  }

  // [xmin, ymin, xmax, ymax], or a disc {"center": [x, y], "radius": r} (a sphere world's).
  void bounds(const json& b, World& world, std::vector<std::string>* warnings) const {
    if (b.is_object()) {
      world.disc_bounds = disc(b, "bounds", warnings);
      return;
    }
    if (!b.is_array() || b.size() != 4)
      fail("bounds", "expected [xmin, ymin, xmax, ymax] or {\"center\": [x, y], \"radius\": r}, got " + abbreviated(b));
    world.bounds = Bounds{number(b[0], "bounds[0]"), number(b[1], "bounds[1]"), number(b[2], "bounds[2]"),
                          number(b[3], "bounds[3]")};
  }

  Disc disc(const json& v, const std::string& object, std::vector<std::string>* warnings) const {
    if (!v.is_object()) fail(object, "expected {\"center\": [x, y], \"radius\": r}, got " + abbreviated(v));
    warn_unknown(v, object, {"center", "radius"}, warnings);
    return {point(required(v, "center", object), object + ".center"),
            number(required(v, "radius", object), object + ".radius")};
  }

  std::vector<Disc> discs(const json& v, std::vector<std::string>* warnings) const {
    if (!v.is_array()) fail("discs", "expected a list of {\"center\": [x, y], \"radius\": r}, got " + abbreviated(v));
    std::vector<Disc> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(disc(v[i], "discs[" + std::to_string(i) + "]", warnings));
    return out;
  }

  std::vector<Wall> walls(const json& v) const {
    if (!v.is_array())
      fail("walls", "expected a list of polylines [[[x, y], [x, y], ...], ...], got " + abbreviated(v));
    std::vector<Wall> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(ring(v[i], "walls[" + std::to_string(i) + "]"));
    return out;
  }

  std::size_t count(const json& v, const std::string& object) const {
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0))
      fail(object, "expected a whole number of at least 0, got " + abbreviated(v));
    return v.get<std::size_t>();
  }
};

}  // namespace

World parse_world(const std::string& text, const std::string& name, std::vector<std::string>* warnings) {
  Reader r(name);
  json root = r.parse(text);
  if (!root.is_object()) r.fail("world", "expected a JSON object at the top level");
  r.refuse_unknown_shapes(root, warnings);

  World world;
  world.source = name;

  if (root.contains("bounds")) r.bounds(root["bounds"], world, warnings);
  if (root.contains("discs")) world.discs = r.discs(root["discs"], warnings);
  if (root.contains("walls")) world.walls = r.walls(root["walls"]);

  if (!root.contains("obstacles") && !root.contains("obstacles_wkt") && !root.contains("discs") &&
      !root.contains("walls"))
    r.fail("world", "missing field \"obstacles\" (use [] for a world without obstacles)");
  if (root.contains("obstacles")) {
    const json& obstacles = root["obstacles"];
    if (!obstacles.is_array())
      r.fail("obstacles", "expected a list of polygons, got " + Reader::abbreviated(obstacles));
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      std::string object = "obstacles[" + std::to_string(i) + "]";
      world.obstacles.push_back(r.polygon(obstacles[i], object, warnings));
      world.obstacle_names.push_back(object);
    }
  }
  if (root.contains("obstacles_wkt")) {
    const json& wkt = root["obstacles_wkt"];
    if (!wkt.is_string()) r.fail("obstacles_wkt", "expected a file name");
    std::filesystem::path wkt_path = wkt.get<std::string>();
    if (wkt_path.is_relative()) wkt_path = std::filesystem::path(name).parent_path() / wkt_path;
    auto polygons = read_wkt_obstacles(wkt_path.string(), name);
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      world.obstacles.push_back(std::move(polygons[i]));
      world.obstacle_names.push_back(wkt_path.filename().string() + " polygon " + std::to_string(i));
    }
  }

  if (root.contains("robot")) {
    const json& robot = root["robot"];
    if (!robot.is_object()) r.fail("robot", "expected {\"parts\": [...]} or {\"disc\": r}");
    r.warn_unknown(robot, "robot", {"parts", "car", "disc"}, warnings);
    if (robot.contains("disc") && !robot.contains("parts")) {
      world.robot.disc = r.number(robot["disc"], "robot.disc");
      if (robot.contains("car")) r.fail("robot", "a disc robot is {\"disc\": r} alone: a car's body is its parts");
    }
  }
  if (root.contains("robot") && !world.robot.disc) {
    const json& robot = root["robot"];
    if (robot.contains("disc")) r.fail("robot", "a robot is {\"parts\": [...]} or {\"disc\": r}, not both");
    const json& parts = r.required(robot, "parts", "robot");
    if (!parts.is_array()) r.fail("robot.parts", "expected a list of polygons");
    // A robot named without parts is almost certainly a mistake, not a point robot.
    if (parts.empty())
      r.fail("robot.parts", "empty: a robot needs at least one part (leave out \"robot\" for a point robot)");
    for (std::size_t i = 0; i < parts.size(); ++i)
      world.robot.parts.push_back(r.ring(parts[i], "robot.parts[" + std::to_string(i) + "]"));
    if (robot.contains("car")) world.robot.car = r.car(robot["car"], warnings);
  }

  if (root.contains("start") != root.contains("goal"))
    r.fail("world", root.contains("start") ? "missing field \"goal\" (start is given)"
                                           : "missing field \"start\" (goal is given)");
  if (root.contains("start"))
    world.queries.push_back(
        r.query(root["start"], root["goal"], "start", "goal", "start/goal", world.robot.car.has_value()));
  if (root.contains("queries")) {
    const json& queries = root["queries"];
    if (!queries.is_array()) r.fail("queries", "expected a list of {\"start\", \"goal\"}");
    for (std::size_t i = 0; i < queries.size(); ++i) {
      std::string object = "queries[" + std::to_string(i) + "]";
      const json& q = queries[i];
      if (!q.is_object()) r.fail(object, "expected {\"start\": [x, y], \"goal\": [x, y]}");
      r.warn_unknown(q, object, {"start", "goal"}, warnings);
      world.queries.push_back(r.query(r.required(q, "start", object), r.required(q, "goal", object), object + ".start",
                                      object + ".goal", object, world.robot.car.has_value()));
    }
  }

  if (root.contains("changes")) {
    const json& changes = root["changes"];
    if (!changes.is_array())
      r.fail("changes", "expected a list of {\"after_moves\", \"add_obstacle\" or \"remove_obstacle\"}");
    for (std::size_t i = 0; i < changes.size(); ++i)
      world.changes.push_back(r.change(changes[i], "changes[" + std::to_string(i) + "]", warnings));
  }

  validate_world(world);
  return world;
}

World read_world(const std::string& path, std::vector<std::string>* warnings) {
  return parse_world(detail::read_text_file(path), path, warnings);
}

std::vector<ExactPoint> read_path(const std::string& path) { return parse_path(detail::read_text_file(path), path); }

std::vector<ExactPoint> parse_path(const std::string& text, const std::string& name) {
  Reader r(name);
  json root = r.parse(text);
  if (!root.is_object()) r.fail("path file", "expected a JSON object {\"path\": [[x, y], ...]}");
  const json& points = r.required(root, "path", "path file");
  if (!points.is_array() || points.empty()) r.fail("path", "expected a non-empty list of points [[x, y], ...]");
  return r.ring(points, "path");
}

std::vector<std::vector<Rational>> read_path_rows(const std::string& path) {
  return parse_path_rows(detail::read_text_file(path), path);
}

std::vector<std::vector<Rational>> parse_path_rows(const std::string& text, const std::string& name) {
  Reader r(name);
  json root = r.parse(text);
  if (!root.is_object()) r.fail("path file", "expected a JSON object {\"path\": [[...], ...]}");
  const json& rows = r.required(root, "path", "path file");
  if (!rows.is_array() || rows.empty()) r.fail("path", "expected a non-empty list of configurations [[...], ...]");
  if (rows.size() > limits::points)
    r.fail("path",
           std::to_string(rows.size()) + " configurations, more than the supported " + std::to_string(limits::points));
  std::vector<std::vector<Rational>> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string object = "path[" + std::to_string(i) + "]";
    if (!rows[i].is_array() || rows[i].empty() || rows[i].size() > 64 || (i > 0 && rows[i].size() != rows[0].size()))
      r.fail(object, "expected a list of numbers as long as path[0]'s");
    out.emplace_back();
    for (std::size_t k = 0; k < rows[i].size(); ++k)
      out.back().push_back(r.number(rows[i][k], object + "[" + std::to_string(k) + "]"));
  }
  return out;
}

}  // namespace polyplan
