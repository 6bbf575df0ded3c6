#pragma once
// A 2D grid whose cells are blocked and freed while it is searched: the graph of an incremental
// search (search/incremental_search.hpp) on a map that changes or is discovered.
//
// The graph is a GridGraph with every cell free (its neighbours never change); what a cell's
// state changes is the cost of the moves touching it, exactly (OctileLength): the conventions'
// straight and diagonal steps (1 and √2 by default), infinity into or out of a blocked cell or,
// unless the conventions cut corners, across the corner of one (the MovingAI rule of
// search/grid_graph.hpp). Cell (x, y) is GridCell y * width + x.
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/octile_length.hpp>

#include <cstdint>
#include <vector>

namespace polyplan {

// A move whose cost a change altered, with the cost it had before.
struct ChangedMove {
  GridCell from = 0, to = 0;
  OctileLength old_cost;
};

class ChangingGrid {
 public:
  // Every cell free. Throws std::invalid_argument for a width or height below 1.
  ChangingGrid(int width, int height, GridConventions conventions = {});

  int width() const { return width_; }
  int height() const { return height_; }
  const GridConventions& conventions() const { return conventions_; }
  const GridGraph& graph() const { return graph_; }
  GridCell cell(int x, int y) const {
    return static_cast<GridCell>(y) * static_cast<GridCell>(width_) + static_cast<GridCell>(x);
  }
  int x(GridCell c) const { return static_cast<int>(c % static_cast<GridCell>(width_)); }
  int y(GridCell c) const { return static_cast<int>(c / static_cast<GridCell>(width_)); }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  bool blocked(GridCell c) const { return blocked_[c] != 0; }
  // Blocks or frees a cell; appends every move whose cost this changed (at most 24) to `changed`.
  // Returns false when the cell already was so (nothing appended).
  bool set_blocked(GridCell c, bool blocked, std::vector<ChangedMove>& changed);

  // The cost of a move between neighbours; infinity where it is blocked.
  OctileLength cost(GridCell from, GridCell to) const;

 private:
  bool blocked_at(int x, int y) const { return blocked_[cell(x, y)] != 0; }

  int width_, height_;
  GridConventions conventions_;
  GridGraph graph_;
  std::vector<std::uint8_t> blocked_;
};

// The move costs, for an incremental search's Costs.
struct ChangingGridCosts {
  const ChangingGrid* grid;
  OctileLength operator()(GridCell from, GridCell to) const { return grid->cost(from, to); }
};

// The exact cost on an empty grid (the octile distance by default), so a consistent heuristic
// under any blocking.
struct ChangingGridDistance {
  const ChangingGrid* grid;
  OctileLength operator()(GridCell a, GridCell b) const {
    return grid->conventions().distance(grid->x(a) - grid->x(b), grid->y(a) - grid->y(b));
  }
};

}  // namespace polyplan
