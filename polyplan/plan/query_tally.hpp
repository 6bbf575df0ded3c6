#pragma once
// The facts every roadmap query reports whatever its answer (plan_report.hpp's shared words):
// search.expanded, search.generated, search.seconds and query_seconds, counted while the query
// runs and written once, when the answer is known (tallied_query).
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <cstddef>

namespace polyplan {

class QueryTally {
 public:
  // What a graph search (search/search_result.hpp) expanded, generated and took.
  template <class SearchResult>
  void count(const SearchResult& result) {
    expanded_ = result.expanded;
    generated_ = result.generated;
    search_seconds_ = result.seconds;
  }

  // The counts (0 when nothing was searched) and the time since the tally was made.
  void write(Facts& facts) const {
    facts.set(SearchFacts::expanded, expanded_);
    facts.set(SearchFacts::generated, generated_);
    facts.set(SearchFacts::seconds, search_seconds_);
    facts.set(QueryFacts::seconds, querying_.seconds());
  }

 private:
  Stopwatch querying_;
  std::size_t expanded_ = 0, generated_ = 0;
  double search_seconds_ = 0;
};

// One query of a planner: `answer(report, tally)` fills the report, returning as soon as it knows
// the answer, and the tally's facts are written into it then.
template <class Configuration, class Answer>
PlanReport<Configuration> tallied_query(Answer&& answer) {
  QueryTally tally;
  PlanReport<Configuration> report;
  answer(report, tally);
  tally.write(report.facts);
  return report;
}

}  // namespace polyplan
