// The course's graph-search homework's report question 2.1 on the sphere world: the same world rasterised at three
// resolutions — too coarse (obstacles fuse, a gap closes), just right (the topology of the free
// space kept), too fine (the same routes for many more cells) — each query planned on the grid
// (start and goal snapped to the nearest free cell) and compared with the exact shortest path of
// the visibility graph. A table on stdout and an SVG per resolution.
// Usage: raster_resolutions [WORLD.json] [OUT_PREFIX] [N1 N2 N3]
//   defaults: data/worlds/sphere_world_polygons.json, "raster", 10 40 200 → raster_n10.svg, ...
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/raster_grid.hpp>
#include <polyplan/grids/raster_planner.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#ifndef POLYPLAN_DATA_DIR
#define POLYPLAN_DATA_DIR "data"
#endif

using namespace polyplan;

int main(int argc, char** argv) {
  const std::string world_file = argc > 1 ? argv[1] : POLYPLAN_DATA_DIR "/worlds/sphere_world_polygons.json";
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
      const PlanReport<ExactPoint> p = visibility.plan(q);
      optimum.push_back(p.found ? p.length : -1);
    }

    for (const std::size_t n : resolutions) {
      const Stopwatch rasterising;
      RasterPlanner planner(cspace, RasterOptions{n});
      const double seconds = rasterising.seconds();
      const Raster& raster = planner.raster();
      const std::size_t blocked = raster.blocked_count();
      std::printf("n = %zu: %zu blocked cells, %zu free cells, rasterised in %.4f s\n", n, blocked, n * n - blocked,
                  seconds);
      std::printf("  %-11s %-6s %-18s %9s %9s %7s %9s\n", "query", "found", "cells", "length", "optimum", "ratio",
                  "expanded");

      std::vector<PlanReport<ExactPoint>> reports;
      std::vector<std::string> labels;
      for (std::size_t i = 0; i < world.queries.size(); ++i) {
        const Query& q = world.queries[i];
        PlanReport<ExactPoint> plan = planner.plan(q, QueryOptions{true});
        plan.recording.expanded.clear();  // ten searches' expansions would hide the cells
        const auto cell = [&](FactKey<FactCell> key) {
          const FactCell c = plan.facts.at(key);
          return cell_text(c[0], c[1]);
        };
        const std::string cells = plan.facts.contains(RasterFacts::start_cell)
                                      ? cell(RasterFacts::start_cell) + ">" + cell(RasterFacts::goal_cell)
                                      : "-";
        if (!plan.found) {
          std::printf("  %-11s %-6s %-18s %s\n", q.name.c_str(), "no", cells.c_str(), plan.why_not.c_str());
        } else {
          std::printf("  %-11s %-6s %-18s %9.3f %9.3f %7.3f %9lld\n", q.name.c_str(), "yes", cells.c_str(), plan.length,
                      optimum[i], optimum[i] > 0 ? plan.length / optimum[i] : 0.0,
                      static_cast<long long>(plan.facts.at(SearchFacts::expanded)));
        }
        labels.push_back("q" + std::to_string(i) +
                         (plan.found ? " " + std::to_string(plan.length).substr(0, 6) : " refused"));
        reports.push_back(std::move(plan));
      }
      svg::Drawing drawing = draw_plan(cspace, reports, labels);
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
