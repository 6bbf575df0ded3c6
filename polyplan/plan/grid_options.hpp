#pragma once
// The grid conventions (search/grid_conventions.hpp) as options, declared once for every planner
// and command that builds a grid: `connectivity` 8|4, `corner-cutting` (true or false) and
// `diagonal-cost` (sqrt2 or a number in [1, 1000]) — Python's connectivity=, corner_cutting=,
// diagonal_cost=.
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/search/grid_conventions.hpp>

#include <string>
#include <string_view>

namespace polyplan {

// Each accessor returns a reference to its field of the options, const or not (a generic lambda:
// [](auto& o) -> auto& { return o.connectivity; }).
template <class Options, class ConnectivityField, class CornerField, class DiagonalField>
OptionTable<Options>& add_grid_options(OptionTable<Options>& table, ConnectivityField connectivity,
                                       CornerField corner_cutting, DiagonalField diagonal_cost) {
  table.add_choice("connectivity", "neighbours of a cell: 8 (with diagonals) or 4", connectivity,
                   Choices<Connectivity>{{"8", Connectivity::full}, {"4", Connectivity::axis_aligned}});
  table.add_field("corner-cutting", corner_cutting,
                  "a diagonal move may pass the corner of a blocked cell (false: both cells beside it must be free)");
  table.add(
      "diagonal-cost", "the cost of a diagonal move (a straight one costs 1)", "sqrt2 or a number in [1, 1000]",
      [diagonal_cost](const Options& o) { return diagonal_cost(o).text(); },
      [diagonal_cost](Options& o, std::string_view text) -> std::optional<std::string> {
        std::string why;
        const auto cost = parse_diagonal_cost(text, why);
        if (!cost) return why;
        diagonal_cost(o) = *cost;
        return std::nullopt;
      },
      in_range(1, 1000));  // the numbers it takes (listings and checks read the range; sqrt2 is one of them)
  return table;
}

// The same for options that keep them in one GridConventions: `conventions(options)` returns it.
template <class Options, class Field>
OptionTable<Options>& add_grid_conventions(OptionTable<Options>& table, Field conventions) {
  return add_grid_options(
      table, [conventions](auto& o) -> auto& { return conventions(o).connectivity; },
      [conventions](auto& o) -> auto& { return conventions(o).corner_cutting; },
      [conventions](auto& o) -> auto& { return conventions(o).diagonal_cost; });
}

}  // namespace polyplan
