#pragma once
// The MovingAI octile benchmark on the implicit grid graph: a map as the benchmark's 8-connected
// grid, its scenario queries as cells (checked against the map), answered with shortest_path and
// one reused workspace, and the scenario file's ninth column read as a verdict within the
// precision it was printed with.
//
// The grid is the one of the benchmark (Sturtevant 2012): straight moves cost 1, diagonal moves
// sqrt(2), a diagonal move never cuts the corner of a blocked cell, and outside the map is blocked.
// Cell (x, y) is GridCell y * width + x (axis 0 the column, axis 1 the row), as GridMap stores it.
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/search_result.hpp>
#include <polyplan/search/search_workspace.hpp>

#include <string>
#include <vector>

namespace polyplan {

// With other conventions (search/grid_conventions.hpp) the grid is no longer the benchmark's: its
// lengths are then not the scenario file's.
GridGraph movingai_grid(const GridMap& map, const GridConventions& conventions = {});

// Throws InputError "SCENARIO_FILE: line N: ..." for the first query made for a map of another
// size, or whose start or goal is outside the map or on a blocked cell. Call it on every query
// before answering any, so that bad input is reported before the long work.
void check_scenarios_fit(const GridMap& map, const std::vector<ScenarioQuery>& queries,
                         const std::string& scenario_file);

// What the scenario file says about a query: whether there is a path, its length as printed, and
// the tolerance within which a computed optimal length agrees with it: half a unit in the last
// printed decimal ("3.41421": 5e-6, "132.40": 0.005, "4": 0.5) plus 2^-24 of the length. The files'
// own arithmetic is that coarse (single precision or a shortened sqrt 2): on 10 of the 15 maps of
// the benchmark data some optimal lengths such as 235.76450199 are printed "235.764", 2e-6 to 6e-6
// beyond half a unit; with the 2^-24 (6e-8 relative) every query of the 15 maps agrees. A length
// of 0 between different cells (the old files) or a negative one means no path.
struct OctileExpectation {
  bool found = false;
  double length = 0;
  double tolerance = 0;
};
OctileExpectation octile_expectation(const ScenarioQuery& query);

// Half a unit in the last printed decimal of a number printed as `text` (exponents allowed).
double half_unit_in_last_place(const std::string& text);

// Whether an answer agrees with the file: both find no path, or both do and the lengths differ by
// at most the tolerance.
bool matches(const OctileExpectation& expected, bool found, double length);

// Answers scenario queries on one map's grid with shortest_path (octile heuristic, GridMoveCost),
// reusing one workspace: the flat versioned table for grids up to dense_vertex_table_fits.
// Not thread-safe (one per thread).
class MovingAiGridSearch {
 public:
  explicit MovingAiGridSearch(const GridMap& map, const GridConventions& conventions = {});

  // Throws std::invalid_argument for a query whose start or goal is not a free cell of the map
  // (check_scenarios_fit reports those as bad input first), and for options shortest_path rejects.
  SearchResult<GridCell> search(const ScenarioQuery& query, const SearchOptions& options = {});

  const GridGraph& graph() const { return graph_; }

 private:
  GridGraph graph_;
  SearchWorkspace<GridCell> workspace_;
};

}  // namespace polyplan
