// Pictures of plans (draw/plan_svg.cpp) from reports built by hand, as any planner would fill
// them: which pieces are drawn, their legend entries with their counts, the theme's colours, and
// what is left out (paths not found, the free-space fill under cells, centres of fine grids).
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include "draw/svg_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

using namespace polyplan;
using polyplan::test::body_of;
using polyplan::test::count;
using polyplan::test::dots_in_group;
using polyplan::test::fill_is;
using polyplan::test::stroke_is;
using polyplan::test::legend_labels;
using polyplan::test::nesting_error;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

using Report = PlanReport<ExactPoint>;
using Labels = std::vector<std::string>;

// The unit obstacle [1, 2]^2 in [0, 4]^2, point robot.
const char* kSquareInABox = R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]],
                                "start": [0, 0], "goal": [4, 4]})";

bool has(const Labels& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

// A roadmap of 5 vertices and 4 edges around the obstacle.
std::shared_ptr<const PlanGraph<ExactPoint>> roadmap() {
  auto graph = std::make_shared<PlanGraph<ExactPoint>>();
  graph->kind = "roadmap";
  graph->vertices = {pt("0", "0"), pt("2", "1"), pt("1", "2"), pt("2", "2"), pt("4", "4")};
  graph->edges = {{0, 1}, {0, 2}, {1, 3}, {3, 4}};
  return graph;
}

// A columns × rows grid of unit cells from (0, 0): the cell (1, 1) blocked, the last column not
// evaluated, the rest free.
std::shared_ptr<const CellGrid> cells(std::size_t columns, std::size_t rows) {
  auto grid = std::make_shared<CellGrid>();
  grid->columns = columns;
  grid->rows = rows;
  grid->states.assign(columns * rows, CellGrid::free);
  grid->states[1 + 1 * columns] = CellGrid::blocked;
  for (std::size_t row = 0; row < rows; ++row) grid->states[columns - 1 + row * columns] = CellGrid::not_evaluated;
  return grid;
}

std::size_t free_cells(const CellGrid& grid) {
  return static_cast<std::size_t>(std::count(grid.states.begin(), grid.states.end(), CellGrid::free));
}

// Three queries' reports: found (with the roadmap, cells and three expanded vertices), not found,
// found (with two expanded vertices).
std::vector<Report> three_reports() {
  std::vector<Report> reports(3);
  reports[0].found = true;
  reports[0].path = {pt("0", "0"), pt("2", "1"), pt("2", "2"), pt("4", "4")};
  reports[0].recording.graph = roadmap();
  reports[0].recording.cells = cells(4, 4);
  reports[0].recording.expanded = {pt("0", "0"), pt("2", "1"), pt("2", "2")};
  reports[1].found = false;
  reports[1].why_not = "start and goal lie in different components of the free space";
  reports[1].path = {pt("0", "4"), pt("4", "0")};  // ignored: not found
  reports[2].found = true;
  reports[2].path = {pt("0", "0"), pt("1", "2"), pt("4", "4")};
  reports[2].recording.expanded = {pt("0", "0"), pt("1", "2")};
  return reports;
}

}  // namespace

TEST(DrawPlan, LegendNamesEveryPieceWithItsCount) {
  const CSpace c(world_from(kSquareInABox));
  const std::string svg = draw_plan(c, three_reports()).str();
  EXPECT_EQ(nesting_error(svg), "");
  const Labels labels = legend_labels(svg);
  for (const char* label :
       {"roadmap edges (4)", "roadmap vertices (5)", "free cells", "blocked cells",
        "grid graph vertices (free cell centres)", "expanded by the search (5)", "path 0", "path 2"})
    EXPECT_TRUE(has(labels, label)) << label;
  EXPECT_FALSE(has(labels, "path 1"));  // not found: nothing to draw
  EXPECT_FALSE(has(labels, "path"));
  // Cells first (under everything), then the C-space, the roadmap, the expanded vertices, the paths.
  EXPECT_EQ(labels.front(), "free cells");
  EXPECT_EQ(labels.back(), "path 2");
  const auto at = [&](const std::string& label) {
    return std::find(labels.begin(), labels.end(), label) - labels.begin();
  };
  EXPECT_LT(at("obstacles"), at("roadmap edges (4)"));
  EXPECT_LT(at("roadmap vertices (5)"), at("expanded by the search (5)"));
  EXPECT_LT(at("expanded by the search (5)"), at("path 0"));
}

TEST(DrawPlan, PathsTakeThePalettesColourOfTheirReport) {
  const CSpace c(world_from(kSquareInABox));
  const std::string body = body_of(draw_plan(c, three_reports()).str());
  EXPECT_EQ(count(body, stroke_is(theme::path_colour(0))), 1u);
  EXPECT_EQ(count(body, stroke_is(theme::path_colour(2))), 1u);
  EXPECT_EQ(body.find(theme::path_colour(1)), std::string::npos);                           // report 1 found nothing
  EXPECT_EQ(dots_in_group(body, fill_is(theme::path_colour(0)) + " stroke=\"none\""), 4u);  // the paths' vertices
  EXPECT_EQ(dots_in_group(body, fill_is(theme::path_colour(2)) + " stroke=\"none\""), 3u);
  EXPECT_EQ(count(body, stroke_is(theme::roadmap)), 1u);  // all edges in one path
  EXPECT_EQ(dots_in_group(body, fill_is(theme::roadmap)), 5u);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::expanded_fill)), 5u);
  EXPECT_NE(body.find(fill_is(theme::blocked_cell_fill)), std::string::npos);
}

TEST(DrawPlan, CellsReplaceTheFreeSpaceFill) {
  const CSpace c(world_from(kSquareInABox));
  const std::string with_cells = draw_plan(c, three_reports()).str();
  EXPECT_FALSE(has(legend_labels(with_cells), "free space (1 component)"));
  // The free cells take the free space's colour, drawn once, as cells (a path of boxes).
  EXPECT_EQ(count(body_of(with_cells), fill_is(theme::free_tints[0].fill)), 1u);
  EXPECT_NE(body_of(with_cells).find("<path fill-rule=\"evenodd\" " + fill_is(theme::free_tints[0].fill)),
            std::string::npos);

  std::vector<Report> without_cells = three_reports();
  without_cells[0].recording.cells.reset();
  const std::string svg = draw_plan(c, without_cells).str();
  const Labels labels = legend_labels(svg);
  EXPECT_TRUE(has(labels, "free space (1 component)"));
  EXPECT_FALSE(has(labels, "free cells"));
  EXPECT_EQ(body_of(svg).find(theme::blocked_cell_fill), std::string::npos);
}

TEST(DrawPlan, OnlyTheFirstGraphIsDrawn) {
  const CSpace c(world_from(kSquareInABox));
  std::vector<Report> reports = three_reports();
  auto tree = std::make_shared<PlanGraph<ExactPoint>>();
  tree->kind = "tree";
  tree->vertices = {pt("0", "0"), pt("3", "0")};
  tree->edges = {{0, 1}};
  reports[2].recording.graph = tree;
  const Labels labels = legend_labels(draw_plan(c, reports).str());
  EXPECT_TRUE(has(labels, "roadmap edges (4)"));
  EXPECT_FALSE(has(labels, "tree edges (1)"));
}

TEST(DrawPlan, LabelsNameThePaths) {
  const CSpace c(world_from(kSquareInABox));
  const Labels labels = legend_labels(draw_plan(c, three_reports(), {"A*", "BFS", "greedy"}).str());
  EXPECT_TRUE(has(labels, "A*"));
  EXPECT_FALSE(has(labels, "BFS"));
  EXPECT_TRUE(has(labels, "greedy"));
  EXPECT_FALSE(has(labels, "path 0"));
}

TEST(DrawPlan, OneReportIsJustPathAndReportsWithoutRecordsDrawTheirPathsOnly) {
  const CSpace c(world_from(kSquareInABox));
  Report report;
  report.found = true;
  report.path = {pt("0", "0"), pt("4", "0"), pt("4", "4")};
  const std::string svg = draw_plan(c, {report}).str();
  EXPECT_EQ(legend_labels(svg), (Labels{"free space (1 component)", "bounds", "C-obstacles (= obstacles, point robot)",
                                        "obstacles", "start", "goal", "path"}));
  EXPECT_EQ(count(body_of(svg), stroke_is(theme::path_colour(0))), 1u);
}

TEST(DrawCells, CentresOnlyUpToSixtyCellsPerSide) {
  for (const auto& [columns, rows, centres] : {std::tuple{4u, 4u, true}, std::tuple{60u, 60u, true},
                                               std::tuple{61u, 10u, false}, std::tuple{10u, 61u, false}}) {
    svg::Drawing d({0, 0, static_cast<double>(columns), static_cast<double>(rows)});
    const auto grid = cells(columns, rows);
    draw_cells(d, *grid);
    const std::string svg = d.str();
    EXPECT_EQ(has(legend_labels(svg), "grid graph vertices (free cell centres)"), centres) << columns << " x " << rows;
    EXPECT_EQ(dots_in_group(body_of(svg), fill_is(theme::cell_vertex)), centres ? free_cells(*grid) : 0u)
        << columns << " x " << rows;
    EXPECT_TRUE(has(legend_labels(svg), "free cells"));
    EXPECT_TRUE(has(legend_labels(svg), "blocked cells"));
  }
}

TEST(DrawCells, RunsOfEqualCellsAreOneBoxEach) {
  // 4 × 4: rows 0, 2 and 3 are one run of three free cells each, row 1 two single free cells
  // around the blocked one; the last column is not evaluated and not drawn.
  svg::Drawing d({0, 0, 4, 4});
  draw_cells(d, *cells(4, 4));
  const std::string body = body_of(d.str());
  const auto free_path = body.find("<path fill-rule=\"evenodd\" " + fill_is(theme::free_tints[0].fill));
  ASSERT_NE(free_path, std::string::npos);
  EXPECT_EQ(count(polyplan::test::attribute_at(body, free_path, "d"), "M"), 5u);
  const auto blocked_path = body.find("<path fill-rule=\"evenodd\" " + fill_is(theme::blocked_cell_fill));
  ASSERT_NE(blocked_path, std::string::npos);
  EXPECT_EQ(count(polyplan::test::attribute_at(body, blocked_path, "d"), "M"), 1u);
}

TEST(DrawPoints, NothingForNoPointsElseDotsAndACount) {
  svg::Drawing empty({0, 0, 1, 1});
  const std::string before = empty.str();
  draw_points(empty, {}, "expanded");
  EXPECT_EQ(empty.str(), before);
  svg::Drawing d({0, 0, 1, 1});
  draw_points(d, {pt("1/2", "1/2"), pt("1/4", "3/4")}, "expanded");
  EXPECT_EQ(legend_labels(d.str()), Labels{"expanded (2)"});
  EXPECT_EQ(dots_in_group(body_of(d.str()), fill_is(theme::expanded_fill)), 2u);
}

TEST(DrawGraph, EdgesAreOnePathAndVerticesDots) {
  svg::Drawing d({0, 0, 4, 4});
  draw_graph(d, *roadmap());
  const std::string body = body_of(d.str());
  const auto edges = body.find(stroke_is(theme::roadmap));
  ASSERT_NE(edges, std::string::npos);
  // One line-to per edge (chained edges share their move-to).
  EXPECT_EQ(count(polyplan::test::attribute_at(body, body.rfind("<path", edges), "d"), "L"), 4u);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::roadmap)), 5u);
  EXPECT_EQ(legend_labels(d.str()), (Labels{"roadmap edges (4)", "roadmap vertices (5)"}));
}
