#pragma once
// A graph search's trace (search/search_trace.hpp) as a report's (PlanReport::trace): each vertex
// with its index in the searched graph and its configuration.
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/search/search_trace.hpp>

#include <cstddef>
#include <vector>

namespace polyplan {

// `at(vertex)` gives a vertex's configuration; vertices must convert to their std::size_t index.
template <class Configuration, class Vertex, class At>
std::vector<PlanExpansion<Configuration>> plan_trace(const SearchTrace<Vertex>& trace, const At& at) {
  std::vector<PlanExpansion<Configuration>> out;
  out.reserve(trace.expansions.size());
  for (const ExpansionRecord<Vertex>& e : trace.expansions) {
    PlanExpansion<Configuration> x;
    x.step = e.step;
    x.vertex = static_cast<std::size_t>(e.vertex);
    x.at = at(e.vertex);
    x.g = e.g;
    x.h = e.h;
    x.f = e.f;
    if (e.backpointer) x.backpointer = static_cast<std::size_t>(*e.backpointer);
    x.open = e.open;
    out.push_back(std::move(x));
  }
  return out;
}

}  // namespace polyplan
