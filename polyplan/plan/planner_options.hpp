#pragma once
// A planner's options are a plain struct with defaults. An OptionTable describes its members once
// (name, meaning, how text sets them), and that one description serves everything else: the
// command line (`--option NAME=VALUE`, or `--NAME VALUE`), `polyplan planners`, and the errors a
// user sees for a bad value.
//
//   struct RasterOptions { std::size_t resolution = 100; Search search = Search::astar; };
//   OptionTable<RasterOptions>()
//       .add("resolution", &RasterOptions::resolution, "cells per side of the bounds")
//       .add("search", &RasterOptions::search, "graph search");
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/search/search_result.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace polyplan {

// The values a number option may take: from min to max, either end open; an unbounded end is
// infinite (and open).
struct OptionRange {
  double min = -std::numeric_limits<double>::infinity(), max = std::numeric_limits<double>::infinity();
  bool min_open = true, max_open = true;

  bool holds(double value) const {
    return (min_open ? value > min : value >= min) && (max_open ? value < max : value <= max);
  }
  // "[0, 1]", "(0, inf)", "[4, 3600]": interval notation.
  std::string text() const;
};
inline OptionRange in_range(double min, double max) { return {min, max, false, false}; }
inline OptionRange at_least(double min) { return {min, std::numeric_limits<double>::infinity(), false, true}; }
inline OptionRange above(double min) { return {min, std::numeric_limits<double>::infinity(), true, true}; }

// What a listing says of one option.
struct OptionInfo {
  std::string name;
  std::string description;
  std::string kind;           // "whole number in [1, inf)", "number in [0, 1]", "true or false", "astar|dijkstra|..."
  std::string default_value;  // as text, from the options struct's defaults
  bool flag = false;          // true or false: the command line takes --NAME and --no-NAME
  std::optional<OptionRange> range;  // a number's: every number option has one
  std::vector<std::string> choices;  // an enumeration's names, in order
};

// NAME=VALUE pairs as the user gave them, in order.
using OptionValues = std::vector<std::pair<std::string, std::string>>;

// The values of an enumeration option with their names, in the order listings show them.
template <class T>
using Choices = std::vector<std::pair<std::string, T>>;

// The graph searches by the names of search/search_result.hpp's one table.
inline Choices<Search> search_choices() {
  Choices<Search> choices;
  for (const auto& s : detail::search_names) choices.emplace_back(std::string(s.name), s.algorithm);
  return choices;
}

namespace detail {
// The whole text as one value of the type; nullopt when it is not one.
std::optional<std::int64_t> parse_whole_number(std::string_view text);
std::optional<double> parse_real_number(std::string_view text);  // finite only
std::optional<bool> parse_flag(std::string_view text);           // true/false, yes/no, on/off, 1/0
std::string show_number(double value);                           // shortest text that reads back the same
std::string show_exact(const Rational& value);                   // a decimal where one is exact ("1.7"), else "p/q"
}  // namespace detail

template <class Options>
class OptionTable {
 public:
  // A member of type bool, an integer, a floating-point number, a Rational (a number the planner
  // decides on exactly: "1.7" is 17/10), std::string or Search. A number takes the values `range`
  // allows (default: every value of its type); one outside is refused naming the option, the value
  // and the range.
  template <class T>
  OptionTable& add(std::string name, T Options::*member, std::string description,
                   std::optional<OptionRange> range = {}) {
    if constexpr (std::is_same_v<T, Search>) {
      return add(std::move(name), member, std::move(description), search_choices());
    } else {
      return add_field(
          std::move(name), [member](auto& o) -> auto& { return o.*member; }, std::move(description), range);
    }
  }

  // The same for the field that `field(options)` returns a reference to (a member of a member).
  template <class Field>
  OptionTable& add_field(std::string name, Field field, std::string description,
                         std::optional<OptionRange> range = {}) {
    using T = std::decay_t<decltype(field(std::declval<Options&>()))>;
    constexpr bool number = (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) || std::is_same_v<T, Rational>;
    if constexpr (number) {
      if (!range) range = range_of<T>();
    }
    Entry e{
        {std::move(name), std::move(description), kind_of<T>(range), {}, std::is_same_v<T, bool>, range, {}}, {}, {}};
    e.show = [field](const Options& o) { return show(field(o)); };
    // [=]: the range is used only when T is a number, and clang warns of an unused capture.
    e.set = [=](Options& o, std::string_view text) -> std::optional<std::string> {
      if (auto why = assign(field(o), text)) return why;
      if constexpr (number)
        if (!holds(*range, field(o))) return "expected a " + kind_of<T>(range);
      return std::nullopt;
    };
    return push(std::move(e));
  }

  // An enumeration set by its names: {{"full", Connectivity::full}, {"axis", ...}}.
  template <class T>
  OptionTable& add(std::string name, T Options::*member, std::string description, Choices<T> names) {
    return add_choice(
        std::move(name), std::move(description), [member](auto& o) -> auto& { return o.*member; }, std::move(names));
  }

  // The same for the enumeration that `field(options)` returns a reference to (a member of a member).
  template <class Field, class T>
  OptionTable& add_choice(std::string name, std::string description, Field field, Choices<T> names) {
    std::string kind;
    std::vector<std::string> choices;
    for (const auto& [text, value] : names) {
      kind += (kind.empty() ? "" : "|") + text;
      choices.push_back(text);
    }
    Entry e{{std::move(name), std::move(description), kind, {}, false, std::nullopt, std::move(choices)}, {}, {}};
    e.show = [field, names](const Options& o) {
      for (const auto& [text, value] : names)
        if (value == field(o)) return text;
      return std::string("?");
    };
    e.set = [field, names, kind](Options& o, std::string_view text) -> std::optional<std::string> {
      for (const auto& [name_text, value] : names)
        if (name_text == text) {
          field(o) = value;
          return std::nullopt;
        }
      return "expected one of " + kind;
    };
    return push(std::move(e));
  }

  // Any other option: how to show its value and how text sets it (nullopt: set; else why not);
  // `range`, for a number, is what listings show (the setter checks it).
  OptionTable& add(std::string name, std::string description, std::string kind,
                   std::function<std::string(const Options&)> show,
                   std::function<std::optional<std::string>(Options&, std::string_view)> set,
                   std::optional<OptionRange> range = {}) {
    return push(Entry{{std::move(name), std::move(description), std::move(kind), {}, false, range, {}},
                      std::move(show),
                      std::move(set)});
  }

  // A check of option `name` that needs the others (the table's checks see one value at a time):
  // `check(options)` after every value is set, nullopt when they agree, else the problem, reported
  // as a bad value of `name` would be.
  OptionTable& require(std::string name, std::function<std::optional<std::string>(const Options&)> check) {
    requirements_.push_back({std::move(name), std::move(check)});
    return *this;
  }

  // Every option, its default read from a default-constructed Options.
  std::vector<OptionInfo> info() const {
    std::vector<OptionInfo> out;
    const Options defaults{};
    for (const Entry& e : entries_) {
      out.push_back(e.info);
      out.back().default_value = e.show(defaults);
    }
    return out;
  }

  // A default-constructed Options with `values` set in order. Throws InputError
  // "planner NAME: option KEY=VALUE: problem" for an unknown name or a value of the wrong kind.
  Options parse(const OptionValues& values, std::string_view planner) const {
    const std::string who = "planner " + std::string(planner) + ": option ";
    return parse_as(
        values, [&who](const std::string& key, const std::string& value) { return who + key + "=" + value + ": "; });
  }

  // The same for a command's own options, given as flags: InputError "--KEY VALUE: problem".
  Options parse_flags(const OptionValues& values) const {
    return parse_as(values,
                    [](const std::string& key, const std::string& value) { return "--" + key + " " + value + ": "; });
  }

  // The same, each problem's message beginning with `where(KEY, VALUE)`: how the caller's users
  // spell the option.
  template <class Where>
  Options parse_as(const OptionValues& values, const Where& where) const {
    Options options{};
    for (const auto& [key, value] : values) {
      const Entry* entry = nullptr;
      for (const Entry& e : entries_)
        if (e.info.name == key) entry = &e;
      if (!entry) throw InputError(where(key, value) + "no such option (" + known() + ")");
      if (auto why = entry->set(options, value)) throw InputError(where(key, value) + *why);
    }
    for (const auto& [name, check] : requirements_)
      if (auto why = check(options)) throw InputError(where(name, given_or_shown(values, name, options)) + *why);
    return options;
  }

 private:
  struct Entry {
    OptionInfo info;
    std::function<std::string(const Options&)> show;
    std::function<std::optional<std::string>(Options&, std::string_view)> set;  // nullopt: set; else why not
  };

  OptionTable& push(Entry e) {
    entries_.push_back(std::move(e));
    return *this;
  }

  // The value of option `name` as the user gave it, else as it is.
  std::string given_or_shown(const OptionValues& values, const std::string& name, const Options& options) const {
    for (auto v = values.rbegin(); v != values.rend(); ++v)
      if (v->first == name) return v->second;
    for (const Entry& e : entries_)
      if (e.info.name == name) return e.show(options);
    return "";
  }

  std::string known() const {
    if (entries_.empty()) return "it takes none";
    std::string names = "its options: ";
    for (std::size_t i = 0; i < entries_.size(); ++i) names += (i ? ", " : "") + entries_[i].info.name;
    return names;
  }

  template <class T>
  static std::string kind_of(const std::optional<OptionRange>& range) {
    if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_integral_v<T>) return "whole number in " + range->text();
    else if constexpr (std::is_floating_point_v<T>) return "number in " + range->text();
    else if constexpr (std::is_same_v<T, Rational>) return "number in " + range->text() + " (exact)";
    else return "text";
  }

  // Whether the range holds the value: a Rational's ends compared exactly (the ends are doubles).
  template <class T>
  static bool holds(const OptionRange& range, const T& value) {
    if constexpr (std::is_same_v<T, Rational>) {
      const auto beyond = [&](double end, int side) {
        if (std::isinf(end)) return false;
        const int sign = cmp(value, Rational(end)) * side;
        return sign > 0 || (sign == 0 && (side < 0 ? range.min_open : range.max_open));
      };
      return !beyond(range.min, -1) && !beyond(range.max, 1);
    } else {
      return range.holds(static_cast<double>(value));
    }
  }

  // Every value of the type: [0, inf) for an unsigned whole number (its own greatest value is
  // refused as out of range when read), any finite number otherwise.
  template <class T>
  static OptionRange range_of() {
    if constexpr (std::is_unsigned_v<T>) return at_least(0);
    else return {};
  }

  template <class T>
  static std::string show(const T& value) {
    if constexpr (std::is_same_v<T, bool>) return value ? "true" : "false";
    else if constexpr (std::is_integral_v<T>) return std::to_string(value);
    else if constexpr (std::is_floating_point_v<T>) return detail::show_number(static_cast<double>(value));
    else if constexpr (std::is_same_v<T, Rational>) return detail::show_exact(value);
    else return value;
  }

  template <class T>
  static std::optional<std::string> assign(T& field, std::string_view text) {
    if constexpr (std::is_same_v<T, bool>) {
      const auto flag = detail::parse_flag(text);
      if (!flag) return "expected true or false";
      field = *flag;
    } else if constexpr (std::is_integral_v<T>) {
      const auto whole = detail::parse_whole_number(text);
      if (!whole) return "expected a whole number";
      const bool fits =
          *whole < 0 ? std::is_signed_v<T> && *whole >= static_cast<std::int64_t>(std::numeric_limits<T>::min())
                     : static_cast<std::uint64_t>(*whole) <= static_cast<std::uint64_t>(std::numeric_limits<T>::max());
      if (!fits) return std::is_unsigned_v<T> && *whole < 0 ? "expected a whole number >= 0" : "out of range";
      field = static_cast<T>(*whole);
    } else if constexpr (std::is_floating_point_v<T>) {
      const auto real = detail::parse_real_number(text);
      if (!real) return "expected a finite number";
      field = static_cast<T>(*real);
    } else if constexpr (std::is_same_v<T, Rational>) {
      std::string why;
      const auto exact = parse_rational(text, &why);
      if (!exact) return "expected a number (" + why + ")";
      field = *exact;
    } else {
      field = T(text);
    }
    return std::nullopt;
  }

  std::vector<Entry> entries_;
  std::vector<std::pair<std::string, std::function<std::optional<std::string>(const Options&)>>> requirements_;
};

// The options of a planner that searches a graph, kept in a SearchOptions member: `name` (the
// algorithm, "search" unless a command calls it otherwise) among `choices`, "weight" (weighted
// A*'s w, at least 1) and "reopen" (weighted A* re-opening closed vertices, SearchOptions::reopen).
template <class Options>
OptionTable<Options>& add_search_options(OptionTable<Options>& table, SearchOptions Options::*member,
                                         std::string name = "search", Choices<Search> choices = search_choices()) {
  std::string described;
  for (const auto& [text, value] : choices)
    described += (described.empty() ? "" : ", ") + std::string(listing_name(value));
  table.add_choice(
      std::move(name), "graph search: " + described, [member](auto& o) -> auto& { return (o.*member).algorithm; },
      std::move(choices));
  const OptionRange weights = at_least(1);
  table.add(
      "weight", "weighted A*: f = g + weight * h", "number in " + weights.text(),
      [member](const Options& o) { return detail::show_number((o.*member).weight); },
      [member, weights](Options& o, std::string_view text) -> std::optional<std::string> {
        const auto weight = detail::parse_real_number(text);
        if (!weight || !weights.holds(*weight)) return "expected a number in " + weights.text();
        (o.*member).weight = *weight;
        return std::nullopt;
      },
      weights);
  table.add_field(
      "reopen", [member](auto& o) -> auto& { return (o.*member).reopen; },
      "weighted A*: expand a closed vertex again when a shorter way to it is found (false: never, the textbook's)");
  return table;
}

}  // namespace polyplan
