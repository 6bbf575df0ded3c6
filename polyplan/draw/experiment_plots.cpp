#include <polyplan/draw/experiment_plots.hpp>

#include <polyplan/draw/theme.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

using svg::Point2;

// The plotting area is [0, kWidth] × [0, kHeight] in the drawing's units; room around it holds
// the ticks' labels, the axes' names and the title.
constexpr double kWidth = 1.6, kHeight = 1.0;
constexpr double kTickPx = 11, kAxisPx = 13, kTitlePx = 14;

std::string tick_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// Round steps (1, 2 or 5 times a power of ten) that cover [lo, hi] with about `count` ticks.
std::vector<double> nice_ticks(double lo, double hi, int count = 6) {
  const double span = hi - lo;
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0 : t);
  return ticks;
}

// A data range with some room: never empty, and [0, hi] when it starts near zero.
std::pair<double, double> padded(double lo, double hi, bool from_zero) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return {0, 1};
  if (from_zero) lo = std::min(lo, 0.0);
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    const double pad = std::max(std::abs(hi) * 0.05, 1e-9);
    return {from_zero ? lo : lo - pad, hi + pad};
  }
  const double pad = 0.05 * (hi - lo);
  return {from_zero && lo == 0 ? 0 : lo - pad, hi + pad};
}

// Axes and frame of a chart whose data run over [x0, x1] × [y0, y1].
class Chart {
 public:
  Chart(double x0, double x1, double y0, double y1, const std::string& title, const std::string& x_name,
        const std::string& y_name, double bottom_room = 0.2)
      : drawing_(svg::Box2{-0.2, -bottom_room, kWidth + 0.05, kHeight + 0.12}, 820), x0_(x0), x1_(x1), y0_(y0),
        y1_(y1) {
    const svg::Style frame{"none", theme::ink, 1.0, 1, 1, ""};
    const svg::Style grid{"none", "#dddddd", 0.8, 1, 1, ""};
    for (double t : nice_ticks(y0, y1)) {
      const double y = to_y(t);
      drawing_.segments({{{0, y}, {kWidth, y}}}, grid);
      const std::string label = tick_text(t);
      drawing_.text({-text_width(label, kTickPx) - 0.015, y - 0.012}, label, kTickPx);
    }
    if (!x_name.empty())
      for (double t : nice_ticks(x0, x1)) {
        const double x = to_x(t);
        drawing_.segments({{{x, 0}, {x, -0.015}}}, frame);
        const std::string label = tick_text(t);
        drawing_.text({x - text_width(label, kTickPx) / 2, -0.055}, label, kTickPx);
      }
    drawing_.polyline({{0, 0}, {kWidth, 0}, {kWidth, kHeight}, {0, kHeight}, {0, 0}}, frame);
    drawing_.text({kWidth / 2 - text_width(x_name, kAxisPx) / 2, -0.11}, x_name, kAxisPx);
    drawing_.text({-0.19, kHeight + 0.02}, y_name, kAxisPx);
    drawing_.text({0.0, kHeight + 0.08}, title, kTitlePx);
  }

  double to_x(double v) const { return (v - x0_) / (x1_ - x0_) * kWidth; }
  double to_y(double v) const { return (v - y0_) / (y1_ - y0_) * kHeight; }
  Point2 at(double x, double y) const { return {to_x(x), to_y(y)}; }
  double text_width(const std::string& text, double px) const {
    return 0.6 * px * static_cast<double>(text.size()) / drawing_.scale();
  }
  svg::Drawing& drawing() { return drawing_; }

 private:
  svg::Drawing drawing_;
  double x0_, x1_, y0_, y1_;
};

svg::Style line(std::size_t i, double px = 2.0) { return svg::Style{"none", theme::path_colour(i), px, 1, 1, ""}; }

std::string title_of(const Experiment& e, std::size_t problem, const std::string& what) {
  return e.name + " · " + e.problems[problem].name + ": " + what + " (" + std::to_string(e.seeds.size()) + " runs)";
}

}  // namespace

svg::Drawing success_rate_plot(const Experiment& e, std::size_t problem,
                               const std::vector<CellStatistics>& statistics) {
  double end = e.time_limit;
  for (const CellStatistics& s : statistics)
    for (double t : s.first_solutions)
      if (std::isfinite(t)) end = std::max(end, t);
  Chart chart(0, end, 0, 100, title_of(e, problem, "success rate"), "time (s)", "solved (%)");
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    const CellStatistics& s = statistics[i];
    std::vector<Point2> steps{chart.at(0, 0)};
    double rate = 0;
    for (std::size_t k = 0; k < s.first_solutions.size() && std::isfinite(s.first_solutions[k]); ++k) {
      steps.push_back(chart.at(s.first_solutions[k], rate));
      rate = 100.0 * static_cast<double>(k + 1) / static_cast<double>(s.runs);
      steps.push_back(chart.at(s.first_solutions[k], rate));
    }
    steps.push_back(chart.at(end, rate));
    chart.drawing().polyline(steps, line(i));
    chart.drawing().legend(e.planners[i].name, line(i), svg::Swatch::line);
  }
  return std::move(chart.drawing());
}

std::optional<svg::Drawing> cost_over_time_plot(const Experiment& e, std::size_t problem,
                                                const std::vector<CellStatistics>& statistics) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  bool any = false;
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    if (!e.planners[i].anytime) continue;
    any = true;
    for (const ValueSummary& c : statistics[i].cost_at)
      for (double v : {c.q1, c.median, c.q3})
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (!any || e.cost_times.empty()) return std::nullopt;
  const auto [y0, y1] = padded(lo, hi, false);
  Chart chart(0, e.time_limit, y0, y1, title_of(e, problem, "best cost, median and quartiles"), "time (s)",
              "best cost (path length)");
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    if (!e.planners[i].anytime) continue;
    const auto& costs = statistics[i].cost_at;
    // The band and the median where they are finite: a run without a solution has no cost yet.
    std::vector<Point2> upper, lower, median;
    for (std::size_t t = 0; t < costs.size(); ++t) {
      if (std::isfinite(costs[t].q3))
        upper.push_back(chart.at(e.cost_times[t], costs[t].q3)),
            lower.push_back(chart.at(e.cost_times[t], costs[t].q1));
      if (std::isfinite(costs[t].median)) median.push_back(chart.at(e.cost_times[t], costs[t].median));
    }
    if (upper.size() > 1) {
      std::vector<Point2> band(upper.begin(), upper.end());
      band.insert(band.end(), lower.rbegin(), lower.rend());
      chart.drawing().polygon({band}, svg::filled(theme::path_colour(i), 0.18, "none", 0));
    }
    if (median.size() > 1) chart.drawing().polyline(median, line(i));
    chart.drawing().points(median, 2.5, svg::filled(theme::path_colour(i), 1, theme::path_colour(i), 0.5));
    chart.drawing().legend(e.planners[i].name, line(i), svg::Swatch::line);
  }
  return std::move(chart.drawing());
}

svg::Drawing box_plot(const Experiment& e, std::size_t problem, const std::vector<CellStatistics>& statistics,
                      BoxPlotOf of) {
  const auto summary = [&](const CellStatistics& s) -> const ValueSummary& {
    return of == BoxPlotOf::time ? s.time : s.length;
  };
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const CellStatistics& s : statistics)
    if (summary(s).count) lo = std::min(lo, summary(s).min), hi = std::max(hi, summary(s).max);
  const auto [y0, y1] = padded(lo, hi, of == BoxPlotOf::time);
  const std::size_t n = std::max<std::size_t>(statistics.size(), 1);
  Chart chart(0, static_cast<double>(n), y0, y1,
              title_of(e, problem, of == BoxPlotOf::time ? "time per run" : "length of the solved runs"), "",
              of == BoxPlotOf::time ? "time (s)" : "length", 0.45);
  svg::Drawing& d = chart.drawing();
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    const double x = static_cast<double>(i) + 0.5, half = 0.3;
    const ValueSummary& s = summary(statistics[i]);
    const svg::Style edge = line(i, 1.5);
    if (s.count) {
      d.polygon(
          {{chart.at(x - half, s.q1), chart.at(x + half, s.q1), chart.at(x + half, s.q3), chart.at(x - half, s.q3)}},
          svg::filled(theme::path_colour(i), 0.25, theme::path_colour(i), 1.5));
      d.segments({{chart.at(x - half, s.median), chart.at(x + half, s.median)},
                  {chart.at(x, s.q3), chart.at(x, s.whisker_high)},
                  {chart.at(x, s.q1), chart.at(x, s.whisker_low)},
                  {chart.at(x - half / 2, s.whisker_high), chart.at(x + half / 2, s.whisker_high)},
                  {chart.at(x - half / 2, s.whisker_low), chart.at(x + half / 2, s.whisker_low)}},
                 edge);
      std::vector<Point2> outliers;
      for (double v : s.outliers)
        if (std::isfinite(v)) outliers.push_back(chart.at(x, v));
      d.points(outliers, 2.5, svg::filled("#ffffff", 1, theme::path_colour(i), 1));
    }
    // The entry's name under its box, slanted so that long names do not collide.
    const Point2 foot = d.to_screen(chart.at(x, y0));
    const std::string label = e.planners[i].name + (s.count ? "" : " (none)");
    d.raw("<text x=\"" + svg::format_number(foot.x) + "\" y=\"" + svg::format_number(foot.y + 14) +
          "\" font-size=\"11\" fill=\"#222\" text-anchor=\"end\" transform=\"rotate(-35 " + svg::format_number(foot.x) +
          " " + svg::format_number(foot.y + 14) + ")\">" + svg::escape_xml(label) + "</text>\n");
  }
  return std::move(chart.drawing());
}

}  // namespace polyplan
