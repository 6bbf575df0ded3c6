#pragma once
// Any planner's answers for a polygon world in one picture, drawn from the reports alone
// (plan/plan_report.hpp): a new planner gets its picture without drawing code of its own.
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <string>
#include <vector>

namespace polyplan {

// The world and its C-space; the cells or the decomposition (when a report carries them: the free
// space is then shown by them); the roadmap or tree (the first report's that carries one); where the searches
// expanded; the clearance disc of a report with the facts clearance, bottleneck.x and
// bottleneck.y; every path found, in the theme's palette, labelled `labels[i]` (default "path" for
// one report, "path i" for several). Reports made with QueryOptions::record carry the graph,
// the cells and the expanded configurations; others draw their paths only.
svg::Drawing draw_plan(const CSpace& cspace, const std::vector<PlanReport<ExactPoint>>& reports,
                       const std::vector<std::string>& labels = {});
// The same over a world with discs or walls (World::round_features): its C-space as
// draw/round_cspace_svg.hpp draws it (the C-obstacles grown, arcs as arcs), the world over it.
svg::Drawing draw_plan(const RoundWorld& world, const std::vector<PlanReport<ExactPoint>>& reports,
                       const std::vector<std::string>& labels = {});

// The pieces, for pictures of one's own (examples/search_comparison draws six searches' paths
// over one roadmap):
// a roadmap or tree, thin and translucent so the paths on top stay readable, vertices as dots;
void draw_graph(svg::Drawing& drawing, const PlanGraph<ExactPoint>& graph);
// cells as runs of free and blocked boxes, and their centres when there are few enough to see;
void draw_cells(svg::Drawing& drawing, const CellGrid& cells);
// convex cells in two alternating pale tints, the walls between them dashed;
void draw_decomposition(svg::Drawing& drawing, const PlanDecomposition<ExactPoint>& decomposition);
// the disc of a path's clearance around the place where the path comes nearest the boundary;
void draw_clearance_disc(svg::Drawing& drawing, svg::Point2 centre, double radius);
// points such as the vertices a search expanded, as small dots with a legend entry.
void draw_points(svg::Drawing& drawing, const std::vector<ExactPoint>& points, const std::string& label);

}  // namespace polyplan
