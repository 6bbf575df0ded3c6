#include <polyplan/homotopy/tether_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/homotopy/class_graph.hpp>
#include <polyplan/homotopy/homotopy_facts.hpp>
#include <polyplan/plan/fact_points.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace polyplan {
namespace {

std::optional<ExactPoint> parse_base(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto comma = text.find(',');
  const auto x = comma == std::string::npos ? std::nullopt : parse_rational(text.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt : parse_rational(text.substr(comma + 1));
  if (!x || !y) throw std::invalid_argument("option tether-base=" + text + ": expected X,Y");
  return ExactPoint{*x, *y};
}

// The tether's taut shapes: a Dijkstra over (vertex, word) from the base, run to its bound.
struct TetherSearch {
  ClassSearch search;
  TetherSearch(const ClassGraph& graph, std::size_t base, Rational bound, std::size_t max_states)
      : search(graph, base, {}, std::move(bound), max_states) {
    while (search.next()) {
    }
  }
  // The taut tether's length in that class (to print), if it is within the bound.
  std::optional<double> length(std::size_t vertex, const Word& word) const {
    const auto id = search.find(vertex, word);
    if (!id) return std::nullopt;
    return search.exact_distance(*id).approximate();
  }
};

}  // namespace

struct TetherPlanner::Impl {
  const CSpace* cspace;
  TetherOptions options;
  std::optional<ExactPoint> base;
  ClassGraph graph;
};

TetherPlanner::TetherPlanner(const CSpace& cspace, TetherOptions options)
    : impl_(std::make_unique<Impl>(Impl{&cspace, options, parse_base(options.tether_base), ClassGraph(cspace)})) {
  if (sgn(options.tether_length) < 0)
    throw std::invalid_argument("option tether-length: expected a number >= 0 (0: no bound)");
}

TetherPlanner::~TetherPlanner() = default;

PlanReport<ExactPoint> TetherPlanner::plan(const Query& q, const QueryOptions& query_options) {
  const Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "tether");
  const auto finish = [&] {
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  const ExactPoint base = r.base.value_or(q.start);
  if (auto why = r.cspace->query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish();
  }
  if (auto hit = r.cspace->collision_at(base)) {
    report.fail(PlanStatus::invalid_query, "the tether base " + to_string(base) + " is not free: " + *hit);
    return finish();
  }
  if (!share_a_component(*r.cspace, base, q.start) || !share_a_component(*r.cspace, q.start, q.goal)) {
    report.fail(PlanStatus::no_path,
                "the tether base, the start and the goal do not lie in one component of the free space");
    return finish();
  }
  ClassGraph graph = r.graph;  // the query's points join a copy
  const std::size_t b = graph.add_point(base);
  const std::size_t s = base == q.start ? b : graph.add_point(q.start), g = graph.add_point(q.goal);
  const std::optional<Rational> L =
      sgn(r.options.tether_length) > 0 ? std::optional<Rational>(r.options.tether_length) : std::nullopt;
  // The tether the robot starts with: straight from the base when that is free, else the shortest.
  Word start_word;
  RootSum start_length;
  if (check_segment(*r.cspace, base, q.start).valid) {
    start_word = graph.signature().segment(base, q.start), start_length = RootSum::polyline({base, q.start});
  } else {
    ClassSearch first(graph, b, {}, std::nullopt, r.options.max_states);
    for (auto id = first.next(); id; id = first.next())
      if (first.state(*id).vertex == s) {
        start_word = first.state(*id).word, start_length = first.exact_distance(*id);
        break;
      }
  }
  if (L && compare(start_length, *L) > 0) {
    report.fail(PlanStatus::no_path, "the tether at the start is " + detail::show_number(start_length.approximate()) +
                                         " long, more than tether-length");
    return finish();
  }
  // G_w: every (vertex, class) the tether reaches within L (without L: within what the robot's
  // path could need, found below).
  std::optional<TetherSearch> tether;
  if (L) tether.emplace(graph, b, *L, r.options.max_states);
  const auto admit = [&](std::size_t v, const Word& w) { return !tether || tether->search.find(v, w).has_value(); };
  ClassSearch robot(graph, s, start_word, std::nullopt, r.options.max_states, admit);
  std::optional<std::size_t> arrived;
  for (auto id = robot.next(); id && !arrived; id = robot.next())
    if (robot.state(*id).vertex == g) arrived = id;
  const bool truncated = robot.truncated() || (tether && tether->search.truncated());
  if (truncated) facts.set(QueryFacts::stopped_by, "state limit");
  if (!arrived) {
    if (tether) facts.set(TetherFacts::reachable, tether->search.states());
    report.fail(truncated ? PlanStatus::limit : PlanStatus::no_path,
                truncated ? "max-states ended the search"
                          : "no class of tether within tether-length (" + detail::show_exact(*L) +
                                ") lets the robot reach the goal");
    return finish();
  }
  report.path = robot.path_to(*arrived);
  if (report.path.size() == 1) report.path.push_back(q.goal);
  report.length = euclidean_length(report.path);
  // Without L, the tether's shapes along the path: it is never longer than the start's tether and
  // the path so far, whose upper bound bounds the search.
  if (!tether) {
    RootSum most = start_length;
    most.add(RootSum::polyline(report.path));
    tether.emplace(graph, b, Rational(most.bounds().upper), r.options.max_states);
  }
  // The tether along the path: its length at each vertex, the largest, its shape at the goal.
  double largest = 0;
  std::vector<std::vector<ExactPoint>> shapes;
  for (const std::size_t id : robot.chain_to(*arrived)) {
    const auto& st = robot.state(id);
    const auto at = tether->search.find(st.vertex, st.word);
    if (!at) throw std::logic_error("tether: the tether to a vertex of the path was not found");
    largest = std::max(largest, tether->search.exact_distance(*at).approximate());
    shapes.push_back(tether->search.path_to(*at));
  }
  const auto& end = robot.state(*arrived);
  facts.set(TetherFacts::word, word_text(end.word));
  facts.set(TetherFacts::length, *tether->length(g, end.word));
  facts.set(TetherFacts::largest, largest);
  facts.set(TetherFacts::at_goal, fact_points(shapes.back()));
  facts.set(TetherFacts::reachable, tether->search.states());
  std::string note = "tether [" + word_text(end.word) + "] " + std::to_string(*tether->length(g, end.word)) +
                     " long at the goal, at most " + std::to_string(largest) + " on the way";
  if (r.options.list_classes) {
    std::string classes;
    for (std::size_t id = 0; id < tether->search.states(); ++id)
      if (tether->search.state(id).vertex == g)
        classes += (classes.empty() ? "[" : "; [") + word_text(tether->search.state(id).word) + "] " +
                   detail::show_number(tether->search.exact_distance(id).approximate());
    facts.set(TetherFacts::classes, classes);
    note += "; the goal within L in the classes " + classes;
  }
  facts.set(QueryFacts::note, note);
  if (query_options.record) {
    using Kind = PlanMark<ExactPoint>::Kind;
    report.recording.marks.push_back({Kind::lines, "taut tether at the path's corners", shapes});
    report.recording.marks.push_back({Kind::lines, "h-signature rays (t1, t2, ...)", graph.signature().ray_segments()});
    report.recording.marks.push_back({Kind::points, "tether base", {{base}}});
  }
  const PathCheck check = check_path(*r.cspace, report.path);
  if (!check.valid) throw std::logic_error("tether: the robot's path is not valid: " + check.reason);
  report.succeed();
  report.certificate = {true, "exact path check (arrangement zone walk) of visibility-graph segments"};
  return finish();
}

PlannerEntry<TranslatingRobot> tether_planner_entry() {
  OptionTable<TetherOptions> table;
  table.add(
      "tether-base", "where the tether is anchored, X,Y (default: the start)", "point X,Y",
      [](const TetherOptions& o) { return o.tether_base; },
      [](TetherOptions& o, std::string_view text) -> std::optional<std::string> {
        o.tether_base = std::string(text);
        return std::nullopt;
      });
  table.add("tether-length", &TetherOptions::tether_length,
            "the tether's length L: its taut shape is never longer (0: no bound)", at_least(0));
  table.add("list-classes", &TetherOptions::list_classes,
            "list every class of tether the goal is reached in within L (fact tether.classes)");
  table.add("max-states", &TetherOptions::max_states,
            "(vertex, word) states each search may make (their words 32 letters each on average)", at_least(1));
  return make_planner_entry<TranslatingRobot, TetherOptions>(
      "tether",
      "a robot on a taut tether of bounded length from a base: the shortest path keeping the tether within L "
      "(h-signature classes)",
      std::move(table),
      [](const CSpace& cspace, const TetherOptions& o) { return std::make_unique<TetherPlanner>(cspace, o); });
}

}  // namespace polyplan
