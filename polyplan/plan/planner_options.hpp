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
#include <polyplan/search/search_result.hpp>

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

// What a listing says of one option.
struct OptionInfo {
  std::string name;
  std::string description;
  std::string kind;           // "whole number", "number", "true or false", "astar|dijkstra|..."
  std::string default_value;  // as text, from the options struct's defaults
  bool flag = false;          // true or false: the command line takes --NAME and --no-NAME
};

// NAME=VALUE pairs as the user gave them, in order.
using OptionValues = std::vector<std::pair<std::string, std::string>>;

// The values of an enumeration option with their names, in the order listings show them.
template <class T>
using Choices = std::vector<std::pair<std::string, T>>;

// The graph searches by the names of search/search_result.hpp's one table.
inline Choices<Search> search_choices() {
  Choices<Search> choices;
  for (const auto& [value, name] : detail::search_names) choices.emplace_back(std::string(name), value);
  return choices;
}

namespace detail {
// The whole text as one value of the type; nullopt when it is not one.
std::optional<std::int64_t> parse_whole_number(std::string_view text);
std::optional<double> parse_real_number(std::string_view text);  // finite only
std::optional<bool> parse_flag(std::string_view text);           // true/false, yes/no, on/off, 1/0
std::string show_number(double value);                           // shortest text that reads back the same
}  // namespace detail

template <class Options>
class OptionTable {
 public:
  // A member of type bool, an integer, a floating-point number, std::string or Search.
  template <class T>
  OptionTable& add(std::string name, T Options::*member, std::string description) {
    if constexpr (std::is_same_v<T, Search>) {
      return add(std::move(name), member, std::move(description), search_choices());
    } else {
      Entry e{{std::move(name), std::move(description), kind_of<T>(), {}, std::is_same_v<T, bool>}, {}, {}};
      e.show = [member](const Options& o) { return show(o.*member); };
      e.set = [member](Options& o, std::string_view text) { return assign(o.*member, text); };
      return push(std::move(e));
    }
  }

  // An enumeration set by its names: {{"full", Connectivity::full}, {"axis", ...}}.
  template <class T>
  OptionTable& add(std::string name, T Options::*member, std::string description, Choices<T> names) {
    return add_choice(std::move(name), std::move(description), [member](auto& o) -> auto& { return o.*member; },
                      std::move(names));
  }

  // The same for the enumeration that `field(options)` returns a reference to (a member of a member).
  template <class Field, class T>
  OptionTable& add_choice(std::string name, std::string description, Field field, Choices<T> names) {
    std::string kind;
    for (const auto& [text, value] : names) kind += (kind.empty() ? "" : "|") + text;
    Entry e{{std::move(name), std::move(description), kind, {}, false}, {}, {}};
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

  // Any other option: how to show its value and how text sets it (nullopt: set; else why not).
  OptionTable& add(std::string name, std::string description, std::string kind,
                   std::function<std::string(const Options&)> show,
                   std::function<std::optional<std::string>(Options&, std::string_view)> set) {
    return push(Entry{{std::move(name), std::move(description), std::move(kind), {}, false}, std::move(show), std::move(set)});
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
    Options options{};
    for (const auto& [key, value] : values) {
      const std::string where = "planner " + std::string(planner) + ": option " + key + "=" + value + ": ";
      const Entry* entry = nullptr;
      for (const Entry& e : entries_)
        if (e.info.name == key) entry = &e;
      if (!entry) throw InputError(where + "no such option (" + known() + ")");
      if (auto why = entry->set(options, value)) throw InputError(where + *why);
    }
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

  std::string known() const {
    if (entries_.empty()) return "it takes none";
    std::string names = "its options: ";
    for (std::size_t i = 0; i < entries_.size(); ++i) names += (i ? ", " : "") + entries_[i].info.name;
    return names;
  }

  template <class T>
  static std::string kind_of() {
    if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_integral_v<T>) return std::is_unsigned_v<T> ? "whole number >= 0" : "whole number";
    else if constexpr (std::is_floating_point_v<T>) return "number";
    else return "text";
  }

  template <class T>
  static std::string show(const T& value) {
    if constexpr (std::is_same_v<T, bool>) return value ? "true" : "false";
    else if constexpr (std::is_integral_v<T>) return std::to_string(value);
    else if constexpr (std::is_floating_point_v<T>) return detail::show_number(static_cast<double>(value));
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
      const bool fits = *whole < 0 ? std::is_signed_v<T> && *whole >= static_cast<std::int64_t>(std::numeric_limits<T>::min())
                                   : static_cast<std::uint64_t>(*whole) <= static_cast<std::uint64_t>(std::numeric_limits<T>::max());
      if (!fits) return std::is_unsigned_v<T> && *whole < 0 ? "expected a whole number >= 0" : "out of range";
      field = static_cast<T>(*whole);
    } else if constexpr (std::is_floating_point_v<T>) {
      const auto real = detail::parse_real_number(text);
      if (!real) return "expected a finite number";
      field = static_cast<T>(*real);
    } else {
      field = T(text);
    }
    return std::nullopt;
  }

  std::vector<Entry> entries_;
};

// The options of a planner that searches a graph, kept in a SearchOptions member: "search" (the
// algorithm) and "weight" (weighted A*'s w, at least 1).
template <class Options>
OptionTable<Options>& add_search_options(OptionTable<Options>& table, SearchOptions Options::*member) {
  table.add_choice("search", "graph search: A*, Dijkstra, BFS, DFS, greedy best-first, weighted A*",
                   [member](auto& o) -> auto& { return (o.*member).algorithm; }, search_choices());
  table.add("weight", "weighted A*: f = g + weight * h", std::string("number >= 1"),
            [member](const Options& o) { return detail::show_number((o.*member).weight); },
            [member](Options& o, std::string_view text) -> std::optional<std::string> {
              const auto weight = detail::parse_real_number(text);
              if (!weight || *weight < 1) return "expected a number of at least 1";
              (o.*member).weight = *weight;
              return std::nullopt;
            });
  return table;
}

}  // namespace polyplan
