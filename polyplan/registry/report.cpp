#include <polyplan/registry/report.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/detail/space_door.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polyplan {
namespace {

// The coordinates of a configuration as the JSON's "path" prints them.
std::vector<double> coordinates(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }
std::vector<double> coordinates(const Pose& p) { return {to_double(p.position.x), to_double(p.position.y), p.degrees}; }
std::vector<double> coordinates(const JointAngles& q) { return q; }
std::vector<double> coordinates(const CarState& s) { return {s.pose.x, s.pose.y, heading_degrees(s.pose)}; }

// Exact coordinates, for the configurations that are exact (none for joint angles and a car's poses).
std::vector<Rational> exact_coordinates(const ExactPoint& p) { return {p.x, p.y}; }
std::vector<Rational> exact_coordinates(const Pose& p) {
  return {p.position.x, p.position.y, p.rotation.sin, p.rotation.cos};
}

template <class Configuration>
Rows rows_of(const std::vector<Configuration>& configurations) {
  Rows rows;
  for (const Configuration& c : configurations) rows.push_back(coordinates(c));
  return rows;
}

// ", astar expanded 9 of 26 generated, roadmap 58 vertices 108 edges": the shared facts a
// report has (plan/plan_facts.hpp).
std::string facts_summary(const Facts& facts) {
  std::string line;
  const auto algorithm = facts.find(SearchFacts::algorithm);
  const auto expanded = facts.find(SearchFacts::expanded), generated = facts.find(SearchFacts::generated);
  if (algorithm && expanded && generated)
    line += ", " + *algorithm + " expanded " + std::to_string(*expanded) + " of " + std::to_string(*generated) +
            " generated";
  const auto vertices = facts.find(RoadmapFacts::vertices), edges = facts.find(RoadmapFacts::edges);
  if (vertices && edges)
    line += ", roadmap " + std::to_string(*vertices) + " vertices " + std::to_string(*edges) + " edges";
  return line;
}

}  // namespace

Report::Report(Typed typed, const detail::SpaceWords& space, std::size_t columns, std::string query,
               std::string planner)
    : typed_(std::move(typed)), space_(&space), columns_(columns), query_(std::move(query)),
      planner_(std::move(planner)) {}

bool Report::found() const {
  return std::visit([](const auto& r) { return r.found; }, typed_);
}
PlanStatus Report::status() const {
  return std::visit([](const auto& r) { return r.status; }, typed_);
}
const std::string& Report::why_not() const {
  return std::visit([](const auto& r) -> const std::string& { return r.why_not; }, typed_);
}
double Report::length() const {
  return std::visit([](const auto& r) { return r.found ? r.length : 0.0; }, typed_);
}
const Certificate& Report::certificate() const {
  return std::visit([](const auto& r) -> const Certificate& { return r.certificate; }, typed_);
}
const Facts& Report::facts() const {
  return std::visit([](const auto& r) -> const Facts& { return r.facts; }, typed_);
}
const std::vector<SolutionImprovement>& Report::improvements() const {
  return std::visit([](const auto& r) -> const std::vector<SolutionImprovement>& { return r.improvements; }, typed_);
}

Rows Report::path() const {
  return std::visit([](const auto& r) { return rows_of(r.path); }, typed_);
}

std::optional<std::vector<std::vector<Rational>>> Report::exact_path() const {
  return std::visit(
      [](const auto& r) -> std::optional<std::vector<std::vector<Rational>>> {
        using Configuration = typename std::decay_t<decltype(r.path)>::value_type;
        if constexpr (requires(const Configuration& c) { exact_coordinates(c); }) {
          if (!r.pieces.empty()) return std::nullopt;  // points between start and goal are irrational
          std::vector<std::vector<Rational>> rows;
          for (const Configuration& c : r.path) rows.push_back(exact_coordinates(c));
          return rows;
        } else {
          return std::nullopt;
        }
      },
      typed_);
}

Recording Report::recording() const {
  return std::visit(
      [](const auto& r) {
        Recording recorded;
        if (r.recording.graph) {
          recorded.graph_kind = r.recording.graph->kind;
          recorded.graph_vertices = rows_of(r.recording.graph->vertices);
          recorded.graph_edges = r.recording.graph->edges;
          recorded.graph_edge_kinds = r.recording.graph->edge_kinds;
        }
        recorded.expanded = rows_of(r.recording.expanded);
        recorded.cells = r.recording.cells;
        if (r.recording.decomposition)
          for (const auto& cell : r.recording.decomposition->cells) recorded.decomposition.push_back(rows_of(cell));
        return recorded;
      },
      typed_);
}

std::vector<TracedExpansion> Report::trace() const {
  return std::visit(
      [](const auto& r) {
        std::vector<TracedExpansion> expansions;
        for (const auto& e : r.recording.trace)
          expansions.push_back({e.step, e.vertex, coordinates(e.at), e.g, e.h, e.f, e.backpointer, e.open});
        return expansions;
      },
      typed_);
}

std::string_view Report::space() const { return space_->description(); }

nlohmann::json Report::to_json() const {
  return std::visit([&](const auto& r) { return plan_json(r, query_); }, typed_);
}

nlohmann::json Report::facts_json() const {
  nlohmann::json all = to_json();
  for (const char* answer : {"query", "found", "status", "length", "path", "path_exact", "segments", "pieces",
                             "why_not", "certified", "certified_by"})
    all.erase(answer);
  return all;
}

std::string Report::summary() const {
  if (!found()) return query_ + ": no path (" + why_not() + ")";
  const auto [moves, arcs] = std::visit(
      [](const auto& r) {
        const auto arc_count = static_cast<std::size_t>(std::count_if(
            r.pieces.begin(), r.pieces.end(), [](const PathPiece& p) { return p.kind == PathPiece::Kind::arc; }));
        return std::pair{r.path.size() - 1 - arc_count, arc_count};
      },
      typed_);
  const std::string_view unit = space_->unit(), steps = space_->steps();
  // Six decimals, as courses print lengths; a world drawn in units of 1e-60 (or 1e60) in six
  // significant digits rather than as 0.000000.
  const double l = length();
  char number[32], text[96];
  std::snprintf(number, sizeof number, l != 0 && (std::abs(l) < 1e-3 || std::abs(l) >= 1e15) ? "%.6g" : "%.6f", l);
  std::snprintf(text, sizeof text, "%.*s(s)", static_cast<int>(steps.size()), steps.data());
  std::string line = query_ + ": length " + number + std::string(unit) + ", " + std::to_string(moves) + " " + text +
                     (arcs ? " and " + std::to_string(arcs) + " arc(s)" : "") + facts_summary(facts()) +
                     space_->summary(facts());
  if (const auto note = facts().find(QueryFacts::note)) line += "; " + *note;
  return line;
}

}  // namespace polyplan
