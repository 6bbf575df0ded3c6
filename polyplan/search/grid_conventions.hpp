#pragma once
// How a 2D grid's cells connect, wherever polyplan builds one (raster, gvd-grid, the replanning
// robot, MovingAI maps): 4 or 8 neighbours, whether a diagonal move may pass the corner of a
// blocked cell, and what a diagonal move costs — √2 exactly, or a number of at least 1 read from
// its text as an exact fraction, so that the exact-cost searches (OctileLength) stay exact: with
// a fraction n/d every cost is counted in units of 1/d (a straight move d, a diagonal n).
//
// The defaults are the MovingAI benchmark's: 8-connected, no corner cutting, diagonals √2.
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/octile_length.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace polyplan {

struct DiagonalCost {
  // √2 when denominator is 0; else numerator / denominator in lowest terms (>= 1).
  std::int64_t numerator = 0, denominator = 0;
  bool is_sqrt2() const { return denominator == 0; }
  double value() const;
  std::string text() const;  // "sqrt2", "1", "1.5"
  friend bool operator==(const DiagonalCost&, const DiagonalCost&) = default;
};

// "sqrt2" (also "√2", "sqrt(2)", and the double nearest √2, which is what Python's math.sqrt(2)
// prints), or a number in [1, 1000] with at most 6 decimals. nullopt with `why` set otherwise.
std::optional<DiagonalCost> parse_diagonal_cost(std::string_view text, std::string& why);

struct GridConventions {
  Connectivity connectivity = Connectivity::full;
  bool corner_cutting = false;  // a diagonal move may pass a blocked cell's corner
  DiagonalCost diagonal_cost{};

  // The exact costs of one move (in units of 1/denominator for a fractional diagonal cost).
  OctileLength straight_step() const;
  OctileLength diagonal_step() const;
  // The shortest cost between cells dx and dy apart on an empty grid: a consistent heuristic.
  OctileLength distance(std::int64_t dx, std::int64_t dy) const;
  // An exact cost in cells, as a double and as text ("3 + 2√2", "7/2", "∞").
  double in_cells(const OctileLength& cost) const;
  std::string text(const OctileLength& cost) const;
  friend bool operator==(const GridConventions&, const GridConventions&) = default;
};

// Gives a 2D grid graph built with the conventions' connectivity their diagonals: cost and corner
// cutting (GridGraph::set_diagonals; nothing changes for the defaults).
void set_diagonals(GridGraph& graph, const GridConventions& conventions);

// The tightest admissible heuristic's metric for a 2D grid graph with square cells: octile (of its
// diagonal cost), or the sum of the axes with 4 neighbours or diagonals that cost 2 or more.
GridMetric square_grid_metric(const GridGraph& graph);

}  // namespace polyplan
