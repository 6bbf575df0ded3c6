#pragma once
// The picture of a potential (`polyplan potential`): log(1 + U) as a heat map over the free
// cells, its contour lines, the direction of descent (−∇U) as arrows, the C-space, the goal, and
// the critical points by kind.
#include <polyplan/draw/svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/reactive/critical_points.hpp>
#include <polyplan/reactive/potential_study.hpp>

#include <vector>

namespace polyplan {

// `map` is the heat map (reactive/potential_map.hpp); `arrows_per_axis` arrows along each side of
// its box.
svg::Drawing draw_potential(const CSpace& cspace, const CellGrid& map, const ObstacleField& field, Vec2 goal,
                            const PotentialParameters& parameters, const std::vector<CriticalPoint>& points,
                            std::size_t arrows_per_axis = 24);

// The picture `polyplan potential --svg` draws of a study: its box's heat map at most 160 cells a
// side (finer says nothing more to the eye and writes megabytes).
svg::Drawing draw_potential_study(const CSpace& cspace, const ObstacleField& field, const PotentialStudy& study);

// The contour lines of a grid of values at `level` (marching squares over the cell centres; cells
// not free are left out): segments in world units.
std::vector<std::pair<svg::Point2, svg::Point2>> contour_segments(const CellGrid& map, double level);

}  // namespace polyplan
