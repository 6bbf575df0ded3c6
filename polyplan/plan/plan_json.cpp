#include <polyplan/plan/plan_json.hpp>

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace polyplan {
namespace {

using json = nlohmann::json;

json value_json(const FactValue& value) {
  return std::visit([](const auto& v) { return json(v); }, value);
}

// "roadmap.vertices" → out["roadmap"]["vertices"].
void put_fact(json& out, const std::string& name, const FactValue& value) {
  const std::vector<std::string> keys = fact_json_keys(name);
  json* at = &out;
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    at = &(*at)[keys[k]];
    if (!at->is_object() && !at->is_null())
      throw std::logic_error("plan_json: the fact " + name + " nests inside a fact that is a value");
  }
  (*at)[keys.back()] = value_json(value);
}

void add_path(json& out, const std::vector<ExactPoint>& path) {
  json doubles = json::array(), exact = json::array();
  for (const ExactPoint& p : path) {
    doubles.push_back({to_double(p.x), to_double(p.y)});
    exact.push_back({to_string(p.x), to_string(p.y)});
  }
  out["path"] = std::move(doubles);
  out["path_exact"] = std::move(exact);
}

void add_path(json& out, const std::vector<JointAngles>& path) {
  json angles = json::array();
  for (const JointAngles& q : path) angles.push_back(q);
  out["path"] = std::move(angles);
}

void add_path(json& out, const std::vector<Pose>& path) {
  json doubles = json::array(), exact = json::array();
  for (const Pose& p : path) {
    doubles.push_back({to_double(p.position.x), to_double(p.position.y), p.degrees});
    exact.push_back(
        {to_string(p.position.x), to_string(p.position.y), to_string(p.rotation.sin), to_string(p.rotation.cos)});
  }
  out["path"] = std::move(doubles);
  out["path_exact"] = std::move(exact);
}

json pose_json(const CarPose& pose) { return json::array({pose.x, pose.y, heading_degrees(pose)}); }

void add_path(json& out, const std::vector<CarState>& path) {
  json poses = json::array(), segments = json::array();
  for (std::size_t i = 0; i < path.size(); ++i) {
    poses.push_back(pose_json(path[i].pose));
    if (i == 0) continue;
    const SteeringSegment& s = path[i].arrival;
    segments.push_back({{"steer", std::string(1, static_cast<char>(s.steer))},
                        {"gear", s.gear},
                        {"length", s.length},
                        {"start", pose_json(path[i - 1].pose)}});
  }
  out["path"] = std::move(poses);
  out["segments"] = std::move(segments);
}

json piece_json(const PathPiece& piece) {
  json out = {{"kind", piece.kind == PathPiece::Kind::arc ? "arc" : "segment"},
              {"from", piece.from},
              {"to", piece.to},
              {"length", piece.length}};
  if (piece.kind == PathPiece::Kind::arc) {
    out["centre"] = piece.centre;
    out["radius"] = piece.radius;
    out["turn"] = piece.counter_clockwise ? "ccw" : "cw";
  }
  return out;
}

// A path of pieces: its points between start and goal are irrational, so no exact text is printed
// for them (the planner decided them exactly; "pieces" say how they join).
void add_pieces(json& out, const std::vector<PathPiece>& pieces) {
  if (pieces.empty()) return;
  out.erase("path_exact");
  json all = json::array();
  for (const PathPiece& piece : pieces) all.push_back(piece_json(piece));
  out["pieces"] = std::move(all);
}

template <class Configuration>
json report_json(const PlanReport<Configuration>& report, const std::string& query) {
  json out = json::object();
  if (!query.empty()) out["query"] = query;
  out["found"] = report.found;
  out["status"] = std::string(to_string(report.status));
  out["length"] = report.found ? json(report.length) : json(nullptr);
  add_path(out, report.path);
  add_pieces(out, report.pieces);
  if (!report.found) out["why_not"] = report.why_not;
  out["certified"] = report.certificate.certified;
  if (report.certificate.certified) out["certified_by"] = report.certificate.method;
  if (report.bottleneck) {
    out["clearance"] = report.bottleneck->clearance;
    out["bottleneck"] = {{"x", report.bottleneck->x}, {"y", report.bottleneck->y}};
  }
  out.update(facts_json(report.facts));
  if (!report.paths.empty()) {
    json paths = json::array();
    for (const PlanPath<Configuration>& p : report.paths) {
      json one = {{"found", true}, {"length", p.length}};
      add_path(one, p.path);
      one.update(facts_json(p.facts));
      paths.push_back(std::move(one));
    }
    out["paths"] = std::move(paths);
  }
  return out;
}

}  // namespace

std::vector<std::string> fact_json_keys(const std::string& name) {
  std::vector<std::string> keys;
  std::size_t begin = 0;
  for (std::size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', begin)) {
    keys.push_back(name.substr(begin, dot - begin));
    begin = dot + 1;
  }
  keys.push_back(name.substr(begin));
  return keys;
}

json facts_json(const Facts& facts) {
  json out = json::object();
  for (const auto& [name, value] : facts.entries()) put_fact(out, name, value);
  return out;
}

json plan_json(const PlanReport<ExactPoint>& report, const std::string& query) { return report_json(report, query); }
json plan_json(const PlanReport<JointAngles>& report, const std::string& query) { return report_json(report, query); }
json plan_json(const PlanReport<Pose>& report, const std::string& query) { return report_json(report, query); }
json plan_json(const PlanReport<CarState>& report, const std::string& query) { return report_json(report, query); }

}  // namespace polyplan
