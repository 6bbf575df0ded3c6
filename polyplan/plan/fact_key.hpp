#pragma once
// A fact's key: the name it is printed under and the type of its value. Planners report facts
// only through keys, which each family declares in its facts header (plan/plan_facts.hpp for the
// shared ones: SearchFacts::expanded is the count "search.expanded"), so that a misspelt or
// mistyped fact does not compile and no layer reads a fact by a string of its own.
//
// The types: bool (a flag), std::int64_t (a count), double (a measure), std::string (a word).
// The name is the JSON key: a dot nests ("search.expanded" is {"search": {"expanded": ...}}).
#include <string_view>

namespace polyplan {

template <class T>
struct FactKey {
  std::string_view name;
};

}  // namespace polyplan
