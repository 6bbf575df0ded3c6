// Seed 000's report question 2.1 on the sphere world: the same world rasterised at three
// resolutions — too coarse (obstacles fuse, a gap closes), just right (the topology of the free
// space kept), too fine (the same routes for many more cells) — each query planned on the grid
// (start and goal snapped to the nearest free cell) and compared with the exact shortest path of
// the visibility graph. A table on stdout and an SVG per resolution.
// Usage: raster_resolutions [WORLD.json] [OUT_PREFIX] [N1 N2 N3]
//   defaults: data/worlds/sphere_world.json, "raster", 10 40 200 → raster_n10.svg, ...
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/draw/world_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/roadmaps/raster_planner.hpp>
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

namespace {

using namespace polyplan;

// Maximal horizontal runs of cells with the given state, as boxes: far fewer than n·n squares.
std::vector<svg::Box2> cell_runs(const Raster& raster, bool blocked) {
  const std::size_t n = raster.cells_per_axis;
  const double x0 = to_double(raster.bounds.xmin), y0 = to_double(raster.bounds.ymin);
  const double w = to_double((raster.bounds.xmax - raster.bounds.xmin) / Rational(mpz_class(n)));
  const double h = to_double((raster.bounds.ymax - raster.bounds.ymin) / Rational(mpz_class(n)));
  std::vector<svg::Box2> runs;
  for (std::size_t y = 0; y < n; ++y)
    for (std::size_t x = 0; x < n;) {
      if (raster.is_blocked(x, y) != blocked) {
        ++x;
        continue;
      }
      const std::size_t first = x;
      while (x < n && raster.is_blocked(x, y) == blocked) ++x;
      runs.push_back({x0 + first * w, y0 + y * h, x0 + x * w, y0 + (y + 1) * h});
    }
  return runs;
}

void draw_cells(svg::Drawing& drawing, const Raster& raster) {
  svg::Style free_style;
  free_style.fill = "#dff1e3";
  free_style.stroke = "none";
  drawing.boxes(cell_runs(raster, false), free_style);
  drawing.legend("free cells", free_style);
  svg::Style blocked_style;
  blocked_style.fill = "#b9b2c9";
  blocked_style.stroke = "#8d84a3";
  blocked_style.stroke_px = 0.4;
  drawing.boxes(cell_runs(raster, true), blocked_style);
  drawing.legend("blocked cells", blocked_style);

  // The graph's vertices, where there are few enough to see one by one.
  if (raster.cells_per_axis > 60) return;
  std::vector<svg::Point2> centres;
  for (std::size_t y = 0; y < raster.cells_per_axis; ++y)
    for (std::size_t x = 0; x < raster.cells_per_axis; ++x)
      if (!raster.is_blocked(x, y)) {
        const ExactPoint c = raster.cell_center(x, y);
        centres.push_back({to_double(c.x), to_double(c.y)});
      }
  svg::Style vertex_style;
  vertex_style.fill = "#6aa77a";
  vertex_style.stroke = "none";
  vertex_style.opacity = 0.6;
  drawing.points(centres, 1.3, vertex_style);
  drawing.legend("grid graph vertices (free cell centres)", vertex_style, svg::Swatch::dot);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string world_file = argc > 1 ? argv[1] : POLYPLAN_DATA_DIR "/worlds/sphere_world.json";
  const std::string prefix = argc > 2 ? argv[2] : "raster";
  std::vector<std::size_t> resolutions{10, 40, 200};
  if (argc == 6) {
    resolutions.clear();
    for (int i = 3; i < 6; ++i) {
      try {
        resolutions.push_back(std::stoul(argv[i]));
      } catch (const std::exception&) {
        std::cerr << "raster_resolutions: not a number of cells: " << argv[i] << '\n';
        return 2;
      }
    }
  } else if (argc > 3) {
    std::cerr << "usage: raster_resolutions [WORLD.json] [OUT_PREFIX] [N1 N2 N3]\n";
    return 2;
  }

  try {
    const World world = read_world(world_file);
    if (world.queries.empty()) throw InputError(world_file + ": world: no start/goal and no queries to plan");
    const CSpace cspace(world);
    cspace.require_free_queries();

    // The reference: exact shortest paths (reduced visibility graph), as `polyplan plan` answers.
    VisibilityGraph visibility(cspace);
    std::vector<double> optimum;
    for (const Query& q : world.queries) {
      const Plan p = visibility.plan(q.start, q.goal);
      optimum.push_back(p.found ? p.length : -1);
    }

    static const char* const palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                          "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
    for (const std::size_t n : resolutions) {
      const auto began = std::chrono::steady_clock::now();
      const Raster raster = rasterize(cspace, n);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      const std::size_t blocked = raster.blocked_count();
      std::printf("n = %zu: %zu blocked cells, %zu free cells, rasterised in %.4f s\n", n, blocked,
                  n * n - blocked, seconds);
      std::printf("  %-11s %-6s %-12s %9s %9s %7s %9s  %s\n", "query", "found", "cells", "length", "optimum",
                  "ratio", "expanded", "checked free");

      const RasterPlanner planner(raster, cspace);
      svg::Drawing drawing(view_box(world, cspace));
      draw_cells(drawing, raster);
      draw_world(drawing, world);
      for (std::size_t i = 0; i < world.queries.size(); ++i) {
        const Query& q = world.queries[i];
        const RasterPlan plan = planner.plan(q);
        const std::string cells = "(" + std::to_string(plan.start_cell_x) + "," + std::to_string(plan.start_cell_y) +
                                  ")>(" + std::to_string(plan.goal_cell_x) + "," + std::to_string(plan.goal_cell_y) + ")";
        if (!plan.found) {
          std::printf("  %-11s %-6s %s\n", q.name.c_str(), "no", plan.why_not_found.c_str());
          continue;
        }
        std::printf("  %-11s %-6s %-12s %9.3f %9.3f %7.3f %9zu  %s\n", q.name.c_str(), "yes", cells.c_str(),
                    plan.length, optimum[i], optimum[i] > 0 ? plan.length / optimum[i] : 0.0, plan.search.expanded,
                    plan.checked_free ? "yes" : ("NO: " + plan.why_not_free).c_str());
        draw_path(drawing, plan.path,
                  "q" + std::to_string(i) + " " + std::to_string(plan.length).substr(0, 6) +
                      (plan.checked_free ? "" : " (not free!)"),
                  palette[i % std::size(palette)]);
      }
      drawing.text({to_double(raster.bounds.xmin), to_double(raster.bounds.ymax) + 0.15},
                   std::to_string(n) + " x " + std::to_string(n) + " cells: " + std::to_string(blocked) + " blocked",
                   14);
      const std::string picture = prefix + "_n" + std::to_string(n) + ".svg";
      drawing.write(picture);
      std::printf("  picture: %s\n\n", picture.c_str());
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
