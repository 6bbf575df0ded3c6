// draw/experiment_plots: the frames fit the data. Time axes go logarithmic when the times span
// decades or end far below the limit, and a box never sits in a sliver of an empty frame — read
// back from the SVG a report prints: its tick labels, the frame, the curves' and boxes' points.
#include <polyplan/draw/experiment_plots.hpp>
#include <polyplan/draw/theme.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace polyplan {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// One problem, `entries` planner entries named p0, p1, ... (anytime ones when `anytime`), with
// `seeds` seeds and a time limit.
Experiment experiment_of(std::size_t entries, std::size_t seeds, double limit, bool anytime = false) {
  Experiment e;
  e.name = "plots";
  e.problems = {{"office", "office.json", ProblemKind::world, "start/goal"}};
  for (std::size_t i = 0; i < entries; ++i) e.planners.push_back({"p" + std::to_string(i), "rrt", {}, anytime});
  for (std::size_t s = 0; s < seeds; ++s) e.seeds.push_back(s + 1);
  e.time_limit = limit;
  return e;
}

// A run of entry `planner` that took `seconds`, improving its solution at each {time, length}
// (unsolved when there is none).
ExperimentRun run_of(std::size_t planner, double seconds, std::vector<SolutionImprovement> improvements = {}) {
  ExperimentRun run;
  run.planner = planner;
  run.seconds = seconds;
  run.solved = !improvements.empty();
  run.status = run.solved ? PlanStatus::solved : PlanStatus::limit;
  run.length = run.solved ? improvements.back().length : 0;
  run.improvements = std::move(improvements);
  return run;
}

// Runs each solved once at its time, `firsts[i]` those of entry i.
ExperimentResults solved_at(const std::vector<std::vector<double>>& firsts) {
  ExperimentResults results;
  for (std::size_t i = 0; i < firsts.size(); ++i)
    for (double t : firsts[i]) results.runs.push_back(run_of(i, t, {{t, 10}}));
  return results;
}

// `count` values evenly from `from` to `to`.
std::vector<double> spread(double from, double to, std::size_t count) {
  std::vector<double> values;
  for (std::size_t k = 0; k < count; ++k)
    values.push_back(from + (to - from) * static_cast<double>(k) / static_cast<double>(count - 1));
  return values;
}

// What the SVG draws: its <path>s with their colours and points (in the picture's pixel frame).
struct DrawnPath {
  std::string fill, stroke;
  std::vector<svg::Point2> points;
};

std::string attribute(const std::string& element, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = element.find(key);
  if (at == std::string::npos) return "";
  const auto from = at + key.size();
  return element.substr(from, element.find('"', from) - from);
}

std::vector<DrawnPath> paths_in(const std::string& svg) {
  std::vector<DrawnPath> paths;
  for (auto at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) {
    const std::string element = svg.substr(at, svg.find("/>", at) - at);
    std::string d = attribute(element, "d");
    if (d.find('h') != std::string::npos) continue;  // a legend's line swatch ("M x yh w"), not data
    DrawnPath path{attribute(element, "fill"), attribute(element, "stroke"), {}};
    std::replace_if(
        d.begin(), d.end(), [](char c) { return c == 'M' || c == 'L' || c == 'Z'; }, ' ');
    std::istringstream in(d);
    for (double x, y; in >> x >> y;) path.points.push_back({x, y});
    paths.push_back(path);
  }
  return paths;
}

// The texts' contents: tick labels, axis names, the title.
std::vector<std::string> texts_in(const std::string& svg) {
  std::vector<std::string> texts;
  for (auto at = svg.find("<text"); at != std::string::npos; at = svg.find("<text", at + 1)) {
    const auto from = svg.find('>', at) + 1;
    texts.push_back(svg.substr(from, svg.find("</text>", from) - from));
  }
  return texts;
}

bool has_text(const std::string& svg, const std::string& text) {
  const auto texts = texts_in(svg);
  return std::find(texts.begin(), texts.end(), text) != texts.end();
}

bool has_text_containing(const std::string& svg, const std::string& part) {
  for (const std::string& text : texts_in(svg))
    if (text.find(part) != std::string::npos) return true;
  return false;
}

svg::Box2 box_of(const std::vector<svg::Point2>& points) {
  svg::BoxAround box;
  for (const svg::Point2& p : points) box.add(p.x, p.y);
  return box.box_or({0, 0, 0, 0});
}

// The plotting area: the closed rectangle drawn in ink (in pixels, y down).
svg::Box2 frame_in(const std::vector<DrawnPath>& paths) {
  for (const DrawnPath& p : paths)
    if (p.stroke == theme::ink && p.points.size() == 5 && p.points[0].x == p.points[4].x &&
        p.points[0].y == p.points[4].y)
      return box_of(p.points);
  ADD_FAILURE() << "no frame";
  return {0, 0, 1, 1};
}

// The unfilled paths drawn in entry i's colour: its success curve, its median, its whiskers.
std::vector<DrawnPath> lines_of(const std::vector<DrawnPath>& paths, std::size_t i) {
  std::vector<DrawnPath> lines;
  for (const DrawnPath& p : paths)
    if (p.stroke == theme::path_colour(i) && p.fill == "none") lines.push_back(p);
  return lines;
}

// The share of the frame's height that entry i's box covers.
double box_share(const std::string& svg, std::size_t i) {
  const auto paths = paths_in(svg);
  const svg::Box2 frame = frame_in(paths);
  for (const DrawnPath& p : paths)
    if (p.fill == theme::path_colour(i)) {
      const svg::Box2 box = box_of(p.points);
      return (box.ymax - box.ymin) / (frame.ymax - frame.ymin);
    }
  ADD_FAILURE() << "no box of entry " << i;
  return 0;
}

svg::Drawing success_plot(const Experiment& e, const ExperimentResults& results) {
  return success_rate_plot(e, 0, experiment_statistics(e, results)[0]);
}

TEST(ExperimentPlots, LogAxisTicksArePowersOfTenAndZeroSitsAtItsLowEnd) {
  EXPECT_EQ((PlotAxis{0.0005, 2, true}.ticks()), (std::vector<double>{0.001, 0.01, 0.1, 1}));
  // Fewer than three decades: 2 and 5 times the powers too.
  EXPECT_EQ((PlotAxis{0.0008, 0.012, true}.ticks()), (std::vector<double>{0.001, 0.002, 0.005, 0.01}));
  EXPECT_GE((PlotAxis{0.0012, 0.0019, true}.ticks().size()), 3u);  // within a decade: still marked
  const PlotAxis axis{0.001, 1, true};
  EXPECT_EQ(axis.to_unit(0), 0);  // a run of 0 s
  EXPECT_EQ(axis.to_unit(1), 1);
  EXPECT_NEAR(axis.to_unit(0.01), 1.0 / 3, 1e-12);
  EXPECT_EQ((PlotAxis{0, 2, false}.ticks()), (std::vector<double>{0, 0.5, 1, 1.5, 2}));
}

TEST(ExperimentPlots, SuccessTimeAxisIsLogAndEndsAtTheDataWhenRunsEndFarBelowTheLimit) {
  const Experiment e = experiment_of(2, 10, 2);
  const std::string svg = success_plot(e, solved_at({spread(0.001, 0.01, 10), spread(0.002, 0.009, 10)})).str();
  EXPECT_TRUE(has_text_containing(svg, "log scale"));
  EXPECT_TRUE(has_text(svg, "0.001"));
  EXPECT_TRUE(has_text(svg, "0.01"));
  EXPECT_FALSE(has_text(svg, "2"));  // the axis ends at the last solution, not at the limit
  const auto paths = paths_in(svg);
  const svg::Box2 frame = frame_in(paths);
  const auto curves = lines_of(paths, 0);
  ASSERT_EQ(curves.size(), 1u);
  std::vector<double> xs;
  for (const svg::Point2& p : curves[0].points) xs.push_back((p.x - frame.xmin) / (frame.xmax - frame.xmin));
  EXPECT_DOUBLE_EQ(xs.front(), 0);  // from the left edge: a log axis has no 0
  EXPECT_DOUBLE_EQ(xs.back(), 1);
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  EXPECT_GT(xs[xs.size() / 2], 0.2);  // the steps spread over the frame, not against the y axis
}

TEST(ExperimentPlots, SuccessTimeAxisIsLogWhenTheTimesSpanMoreThanADecade) {
  const Experiment e = experiment_of(1, 10, 2);
  const std::string svg = success_plot(e, solved_at({spread(0.05, 1.9, 10)})).str();
  EXPECT_TRUE(has_text_containing(svg, "log scale"));
  EXPECT_TRUE(has_text(svg, "0.1"));
  EXPECT_TRUE(has_text(svg, "1"));
}

TEST(ExperimentPlots, SuccessTimeAxisStaysLinearToTheLimitWhenTheRunsFillIt) {
  const Experiment e = experiment_of(1, 10, 2);
  const std::string svg = success_plot(e, solved_at({spread(0.5, 1.9, 10)})).str();
  EXPECT_FALSE(has_text_containing(svg, "log scale"));
  EXPECT_TRUE(has_text(svg, "time (s)"));
  for (const char* tick : {"0", "0.5", "1", "1.5", "2"}) EXPECT_TRUE(has_text(svg, tick)) << tick;
  const auto paths = paths_in(svg);
  const svg::Box2 frame = frame_in(paths);
  const auto curve = lines_of(paths, 0).at(0).points;
  EXPECT_NEAR((curve[curve.size() - 2].x - frame.xmin) / (frame.xmax - frame.xmin), 1.9 / 2, 1e-6);
}

TEST(ExperimentPlots, SuccessTimeAxisEndsAtTheLastSolutionBeforeHalfTheLimit) {
  const Experiment e = experiment_of(1, 10, 2);
  const std::string svg = success_plot(e, solved_at({spread(0.3, 0.9, 10)})).str();
  EXPECT_FALSE(has_text_containing(svg, "log scale"));
  EXPECT_TRUE(has_text(svg, "time (s, limit 2 s)"));
  EXPECT_FALSE(has_text(svg, "2"));
  const auto paths = paths_in(svg);
  const svg::Box2 frame = frame_in(paths);
  const auto curve = lines_of(paths, 0).at(0).points;
  EXPECT_GT((curve[curve.size() - 2].x - frame.xmin) / (frame.xmax - frame.xmin), 0.9);  // the last step
}

TEST(ExperimentPlots, SuccessPlotOfUnsolvedRunsOrRunsOfZeroSeconds) {
  const Experiment e = experiment_of(1, 4, 2);
  ExperimentResults unsolved;
  for (int k = 0; k < 4; ++k) unsolved.runs.push_back(run_of(0, 2));
  const std::string none = success_plot(e, unsolved).str();
  EXPECT_TRUE(has_text(none, "time (s)"));  // no time to fit: linear to the limit
  EXPECT_TRUE(has_text(none, "2"));
  const auto none_paths = paths_in(none);
  const svg::Box2 frame = frame_in(none_paths);
  const svg::Box2 flat = box_of(lines_of(none_paths, 0).at(0).points);
  EXPECT_DOUBLE_EQ(flat.xmin, frame.xmin);
  EXPECT_DOUBLE_EQ(flat.xmax, frame.xmax);
  EXPECT_DOUBLE_EQ(flat.ymin, frame.ymax);  // at 0 %

  // A run of 0 s on a log axis steps up at its left edge; the curve stays in the frame.
  const std::string zero = success_plot(e, solved_at({{0, 0.001, 0.002, 0.004}})).str();
  EXPECT_TRUE(has_text_containing(zero, "log scale"));
  const auto paths = paths_in(zero);
  const svg::Box2 zero_frame = frame_in(paths);
  const auto curve = lines_of(paths, 0).at(0).points;
  EXPECT_DOUBLE_EQ(curve[1].x, zero_frame.xmin);
  EXPECT_DOUBLE_EQ(curve[2].x, zero_frame.xmin);
  const svg::Box2 drawn = box_of(curve);
  EXPECT_GE(drawn.xmin, zero_frame.xmin);
  EXPECT_LE(drawn.xmax, zero_frame.xmax);
  EXPECT_LT(curve[3].x, curve[5].x);
}

TEST(ExperimentPlots, TimeBoxOfRunsNearTheLimitFillsTheFrame) {
  const Experiment e = experiment_of(1, 10, 2);
  ExperimentResults results;
  for (double t : spread(1.9, 2.0, 10)) results.runs.push_back(run_of(0, t));
  const std::string svg = box_plot(e, 0, experiment_statistics(e, results)[0], BoxPlotOf::time).str();
  EXPECT_GT(box_share(svg, 0), 0.3);  // not a sliver on top of an empty frame from 0
  EXPECT_FALSE(has_text(svg, "0"));
  EXPECT_FALSE(has_text_containing(svg, "log scale"));
}

TEST(ExperimentPlots, TimeBoxesGoLogWhenTheTimesSpanDecades) {
  const Experiment e = experiment_of(2, 10, 2);
  ExperimentResults results;
  for (double t : spread(0.001, 0.01, 10)) results.runs.push_back(run_of(0, t));
  for (double t : spread(0.5, 1.0, 10)) results.runs.push_back(run_of(1, t));
  const std::string svg = box_plot(e, 0, experiment_statistics(e, results)[0], BoxPlotOf::time).str();
  EXPECT_TRUE(has_text_containing(svg, "log scale"));
  for (const char* tick : {"0.001", "0.01", "0.1", "1"}) EXPECT_TRUE(has_text(svg, tick)) << tick;
  EXPECT_GT(box_share(svg, 0), 0.08);  // the fast entry's box is not flattened against zero
}

TEST(ExperimentPlots, LengthBoxesFitLengthsFarFromZeroAndStayLinear) {
  const Experiment e = experiment_of(2, 10, 2);
  ExperimentResults results;
  for (double length : spread(10, 12, 10)) results.runs.push_back(run_of(0, 1, {{1, length}}));
  for (double length : spread(10.5, 11.5, 10)) results.runs.push_back(run_of(1, 1, {{1, length}}));
  const std::string svg = box_plot(e, 0, experiment_statistics(e, results)[0], BoxPlotOf::length).str();
  EXPECT_GT(box_share(svg, 0), 0.3);
  EXPECT_FALSE(has_text(svg, "0"));

  ExperimentResults spread_out;  // lengths over two decades: a length axis stays linear
  for (double length : spread(1, 100, 10)) spread_out.runs.push_back(run_of(0, 1, {{1, length}}));
  const std::string linear = box_plot(e, 0, experiment_statistics(e, spread_out)[0], BoxPlotOf::length).str();
  EXPECT_FALSE(has_text_containing(linear, "log scale"));
  EXPECT_TRUE(has_text(linear, "0"));  // from zero, which is near these
}

TEST(ExperimentPlots, CostTimeAxisGoesLogWhenTheCostTimesSpanDecades) {
  Experiment e = experiment_of(1, 4, 5, true);
  ExperimentResults results;
  for (int k = 0; k < 4; ++k) results.runs.push_back(run_of(0, 5, {{0.02, 12.0 - k}, {0.3, 10.0 - k}, {2, 9.0 - k}}));
  e.cost_times = {0.05, 0.1, 0.5, 1, 5};
  const auto log_plot = cost_over_time_plot(e, 0, experiment_statistics(e, results)[0]);
  ASSERT_TRUE(log_plot);
  const std::string svg = log_plot->str();
  EXPECT_TRUE(has_text_containing(svg, "log scale"));
  EXPECT_TRUE(has_text(svg, "0.1"));
  const auto paths = paths_in(svg);
  const svg::Box2 frame = frame_in(paths);
  const auto median = lines_of(paths, 0).at(0).points;  // one point per cost time
  ASSERT_EQ(median.size(), 5u);
  EXPECT_GT((median[1].x - frame.xmin) / (frame.xmax - frame.xmin), 0.1);  // 0.1 s is not against the axis

  e.cost_times = {1, 2, 3, 4, 5};
  const std::string linear = cost_over_time_plot(e, 0, experiment_statistics(e, results)[0])->str();
  EXPECT_TRUE(has_text(linear, "time (s)"));
  EXPECT_TRUE(has_text(linear, "0"));
}

}  // namespace
}  // namespace polyplan
