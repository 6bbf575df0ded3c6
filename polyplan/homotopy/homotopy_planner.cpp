#include <polyplan/homotopy/homotopy_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/homotopy/class_graph.hpp>
#include <polyplan/homotopy/homotopy_facts.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <optional>
#include <set>
#include <stdexcept>

namespace polyplan {

struct HomotopyPlanner::Impl {
  const CSpace* cspace;
  HomotopyOptions options;
  ClassGraph graph;
};

HomotopyPlanner::HomotopyPlanner(const CSpace& cspace, HomotopyOptions options)
    : impl_(std::make_unique<Impl>(Impl{&cspace, options, ClassGraph(cspace)})) {
  if (options.classes == 0) throw std::invalid_argument("option classes=0: expected at least 1");
  if (sgn(options.max_length) < 0)
    throw std::invalid_argument("option max-length: expected a number >= 0 (0: no bound)");
}

HomotopyPlanner::~HomotopyPlanner() = default;

PlanReport<ExactPoint> HomotopyPlanner::plan(const Query& q, const QueryOptions& query_options) {
  Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, "homotopy");
  facts.set(HomotopyFacts::rays, r.graph.signature().rays().size());
  const auto finish = [&] {
    facts.set(HomotopyFacts::classes, report.paths.size());
    facts.set(QueryFacts::seconds, querying.seconds());
    return std::move(report);
  };
  if (auto why = r.cspace->query_not_free(q)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish();
  }
  if (!share_a_component(*r.cspace, q.start, q.goal)) {
    report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
    return finish();
  }
  // The query's points join a copy of the graph, so that queries never see each other's.
  ClassGraph graph = r.graph;
  const std::size_t start = graph.add_point(q.start), goal = graph.add_point(q.goal);
  const std::optional<Rational> bound =
      sgn(r.options.max_length) > 0 ? std::optional<Rational>(r.options.max_length) : std::nullopt;
  ClassSearch search(graph, start, {}, bound, r.options.max_states);
  std::set<Word> met;
  while (report.paths.size() < r.options.classes) {
    const auto id = search.next();
    if (!id) break;
    const auto& s = search.state(*id);
    if (s.vertex != goal || !met.insert(s.word).second) continue;
    PlanPath<ExactPoint> found{search.path_to(*id), 0, {}, {}};
    if (found.path.size() == 1) found.path.push_back(q.goal);
    found.length = euclidean_length(found.path);
    found.label = word_text(s.word);
    found.facts.set(HomotopyFacts::path_word, found.label);
    report.paths.push_back(std::move(found));
  }
  facts.set(HomotopyFacts::states, search.states());
  if (search.truncated()) facts.set(QueryFacts::stopped_by, "state limit");
  if (report.paths.empty()) {
    if (search.truncated())
      report.fail(PlanStatus::limit,
                  "max-states (" + std::to_string(r.options.max_states) + ") ended the search before the goal");
    else
      report.fail(PlanStatus::not_found,
                  "no path within max-length (" + detail::show_exact(r.options.max_length) + ")");
    return finish();
  }
  for (const auto& p : report.paths)
    if (const PathCheck check = check_path(*r.cspace, p.path); !check.valid)
      throw std::logic_error("homotopy: a path of class " + p.label + " is not valid: " + check.reason);
  report.succeed();
  report.path = report.paths.front().path;
  report.length = report.paths.front().length;
  report.certificate = {true, "exact path check (arrangement zone walk) of visibility-graph segments"};
  facts.set(HomotopyFacts::word, report.paths.front().label);
  if (query_options.record)
    report.recording.marks.push_back(
        {PlanMark<ExactPoint>::Kind::lines, "h-signature rays (t1, t2, ...)", r.graph.signature().ray_segments()});
  // What the program prints after its summary line: every class, by length.
  std::string note = std::to_string(report.paths.size()) + " class(es) by length:";
  for (const auto& p : report.paths) note += " " + std::to_string(p.length) + " [" + p.label + "]";
  if (report.paths.size() < r.options.classes)
    note += " (" + std::to_string(r.options.classes) + " asked for: no more within the bounds)";
  facts.set(QueryFacts::note, note);
  return finish();
}

PlannerEntry<TranslatingRobot> homotopy_planner_entry() {
  OptionTable<HomotopyOptions> table;
  table.add("classes", &HomotopyOptions::classes,
            "how many homotopy classes: the shortest path of each, in order of length (the k-th may wind k times "
            "round an obstacle, so K classes hold about K^2/2 vertices: at most 100)",
            in_range(1, 100));
  table.add("max-length", &HomotopyOptions::max_length, "no path longer than this (0: no bound)", at_least(0));
  table.add("max-states", &HomotopyOptions::max_states,
            "(vertex, word) states the search may make (their words 32 letters each on average)", at_least(1));
  return make_planner_entry<TranslatingRobot, HomotopyOptions>(
      "homotopy",
      "the shortest path of each of the K shortest homotopy classes (h-signature words over the visibility graph)",
      std::move(table),
      [](const CSpace& cspace, const HomotopyOptions& o) { return std::make_unique<HomotopyPlanner>(cspace, o); });
}

}  // namespace polyplan
