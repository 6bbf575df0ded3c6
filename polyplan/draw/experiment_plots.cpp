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
// The picture is kWidthPx wide, from 0.2 units left of the plotting area to 0.05 right of it.
constexpr double kWidthPx = 820, kPixelsPerUnit = kWidthPx / (kWidth + 0.25);
constexpr double kTickPx = 11, kAxisPx = 13, kTitlePx = 14;

std::string tick_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
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

// `digit` × 10^`exponent`, divided rather than multiplied for negative exponents so that 0.001 is
// the double nearest 0.001 and its label reads "0.001".
double decade_value(double digit, int exponent) {
  return exponent < 0 ? digit / std::pow(10.0, -exponent) : digit * std::pow(10.0, exponent);
}

// `digits` times the powers of ten in [lo, hi] (0 < lo), every `every`-th power only, so that an
// axis of many decades keeps its labels apart.
std::vector<double> decade_ticks(double lo, double hi, const std::vector<double>& digits, int every = 1) {
  std::vector<double> ticks;
  const int first = static_cast<int>(std::floor(std::log10(lo))), last = static_cast<int>(std::ceil(std::log10(hi)));
  for (int e = first; e <= last; ++e)
    for (double digit : digits) {
      const double t = decade_value(digit, e);
      if (e % every == 0 && t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
    }
  return ticks;
}

// Powers of ten mark a log axis; over few decades they are too few to read a value by, hence 2 and
// 5 times them, and within a decade (where even those may miss) linear steps.
std::vector<double> log_ticks(double lo, double hi) {
  const double decades = std::log10(hi / lo);
  if (decades >= 3) return decade_ticks(lo, hi, {1}, std::max(1, static_cast<int>(std::ceil(decades / 10))));
  std::vector<double> ticks = decade_ticks(lo, hi, {1, 2, 5});
  return ticks.size() >= 3 ? ticks : nice_ticks(lo, hi);
}

// The finite values' range, of those above `floor` only; {+inf, −inf} (lo > hi) when there is none.
std::pair<double, double> finite_range(const std::vector<double>& values,
                                       double floor = -std::numeric_limits<double>::infinity()) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (std::isfinite(v) && v > floor) lo = std::min(lo, v), hi = std::max(hi, v);
  return {lo, hi};
}

// Positive values over more than a decade: on a linear axis all but the largest would crowd
// against zero.
bool spans_decade(const std::vector<double>& values) {
  const auto [lo, hi] = finite_range(values, 0);
  return lo <= hi && hi > 10 * lo;
}

// A log axis over the positive values with 5% of its decades as room at each end; a factor of 2
// each side when they are all equal, so that the axis has a length and a tick or two.
PlotAxis log_fit(const std::vector<double>& values) {
  const auto [lo, hi] = finite_range(values, 0);
  const double room = std::pow(10.0, lo == hi ? std::log10(2.0) : 0.05 * std::log10(hi / lo));
  return {lo / room, hi * room, true};
}

// A linear axis over the finite values with 5% room at each end ([0, 1] for none). With
// `zero_if_near`, from zero when that adds at most a fifth of the data's span below them: the
// data then read against the origin at little cost, while data far from zero fill the frame.
PlotAxis linear_fit(const std::vector<double>& values, bool zero_if_near) {
  auto [lo, hi] = finite_range(values);
  if (!(lo <= hi)) return {0, 1, false};
  if (zero_if_near && lo >= 0 && lo <= 0.2 * (hi - lo)) lo = 0;
  const double pad = hi > lo ? 0.05 * (hi - lo) : hi != 0 ? 0.05 * std::abs(hi) : 1;
  return {lo == 0 ? 0 : lo - pad, hi + pad, false};
}

// The axis for `values`: log when `may_log` and they span more than a decade, else linear.
PlotAxis fit(const std::vector<double>& values, bool may_log, bool zero_if_near) {
  return may_log && spans_decade(values) ? log_fit(values) : linear_fit(values, zero_if_near);
}

// "time (s)", with what a reader needs to read it: a log scale, an axis that stops short of the
// time limit.
std::string time_name(const PlotAxis& axis, double limit) {
  std::string name = "time (s";
  if (axis.log) name += ", log scale";
  if (axis.hi < limit) name += ", limit " + tick_text(limit) + " s";
  return name + ")";
}

// Axes and frame of a chart whose data are mapped by `x` and `y` onto [0, kWidth] × [0, kHeight].
class Chart {
 public:
  Chart(PlotAxis x, PlotAxis y, const std::string& title, const std::string& x_name, const std::string& y_name,
        double bottom_room = 0.2)
      : drawing_(svg::Box2{-0.2, -bottom_room, kWidth + 0.05, kHeight + 0.12}, kWidthPx), x_(x), y_(y) {
    draw_y_ticks();
    if (!x_name.empty()) draw_x_ticks();
    drawing_.polyline({{0, 0}, {kWidth, 0}, {kWidth, kHeight}, {0, kHeight}, {0, 0}}, frame_style());
    drawing_.text({kWidth / 2 - text_width(x_name, kAxisPx) / 2, -0.11}, x_name, kAxisPx);
    drawing_.text({-0.19, kHeight + 0.02}, y_name, kAxisPx);
    drawing_.text({0.0, kHeight + 0.08}, title, kTitlePx);
  }

  const PlotAxis& x() const { return x_; }
  const PlotAxis& y() const { return y_; }
  double to_x(double v) const { return x_.to_unit(v) * kWidth; }
  double to_y(double v) const { return y_.to_unit(v) * kHeight; }
  Point2 at(double x, double y) const { return {to_x(x), to_y(y)}; }
  double text_width(const std::string& text, double px) const {
    return 0.6 * px * static_cast<double>(text.size()) / drawing_.scale();
  }
  svg::Drawing& drawing() { return drawing_; }

 private:
  static svg::Style frame_style() { return {"none", theme::ink, 1.0, 1, 1, ""}; }

  // A grid line and a label at each of the y axis' ticks.
  void draw_y_ticks() {
    const svg::Style grid{"none", "#dddddd", 0.8, 1, 1, ""};
    for (double t : y_.ticks()) {
      const double y = to_y(t);
      drawing_.segments({{{0, y}, {kWidth, y}}}, grid);
      const std::string label = tick_text(t);
      drawing_.text({-text_width(label, kTickPx) - 0.015, y - 0.012}, label, kTickPx);
    }
  }

  // A mark and a label under the frame at each of the x axis' ticks.
  void draw_x_ticks() {
    for (double t : x_.ticks()) {
      const double x = to_x(t);
      drawing_.segments({{{x, 0}, {x, -0.015}}}, frame_style());
      const std::string label = tick_text(t);
      drawing_.text({x - text_width(label, kTickPx) / 2, -0.055}, label, kTickPx);
    }
  }

  svg::Drawing drawing_;
  PlotAxis x_, y_;
};

svg::Style line(std::size_t i, double px = 2.0) { return svg::Style{"none", theme::path_colour(i), px, 1, 1, ""}; }

std::string title_of(const Experiment& e, std::size_t problem, const std::string& what) {
  return e.name + " · " + e.problems[problem].name + ": " + what + " (" + std::to_string(e.seeds.size()) + " runs)";
}

// The success plot's time axis for the first solutions `times` (see success_rate_plot).
PlotAxis success_axis(const std::vector<double>& times, double limit) {
  const auto [first, last] = finite_range(times, 0);
  const bool any = first <= last;
  if (any && (last > 10 * first || last < limit / 10)) return log_fit(times);
  // A curve that would fill less than half a frame up to the limit gets a frame that ends at it.
  if (any && last < limit / 2) return {0, last * 1.05, false};
  const double end = std::max(limit, any ? last : 0.0);  // a run may end a little past the limit
  return {0, end > 0 ? end : 1, false};
}

// An entry's success curve: a step up at each first solution, from the axis' left end (a log axis
// has no 0) to its right end.
std::vector<Point2> success_steps(const Chart& chart, const CellStatistics& s) {
  std::vector<Point2> steps{chart.at(chart.x().lo, 0)};
  double rate = 0;
  for (std::size_t k = 0; k < s.first_solutions.size() && std::isfinite(s.first_solutions[k]); ++k) {
    steps.push_back(chart.at(s.first_solutions[k], rate));
    rate = 100.0 * static_cast<double>(k + 1) / static_cast<double>(s.runs);
    steps.push_back(chart.at(s.first_solutions[k], rate));
  }
  steps.push_back(chart.at(chart.x().hi, rate));
  return steps;
}

// Entry i's median best cost at each of `times` and its quartiles' band, where they are finite: a
// run without a solution has no cost yet.
void draw_costs(Chart& chart, const std::vector<double>& times, const std::vector<ValueSummary>& costs, std::size_t i) {
  std::vector<Point2> upper, lower, median;
  for (std::size_t t = 0; t < costs.size(); ++t) {
    if (std::isfinite(costs[t].q3))
      upper.push_back(chart.at(times[t], costs[t].q3)), lower.push_back(chart.at(times[t], costs[t].q1));
    if (std::isfinite(costs[t].median)) median.push_back(chart.at(times[t], costs[t].median));
  }
  if (upper.size() > 1) {
    std::vector<Point2> band(upper.begin(), upper.end());
    band.insert(band.end(), lower.rbegin(), lower.rend());
    chart.drawing().polygon({band}, svg::filled(theme::path_colour(i), 0.18, "none", 0));
  }
  if (median.size() > 1) chart.drawing().polyline(median, line(i));
  chart.drawing().points(median, 2.5, svg::filled(theme::path_colour(i), 1, theme::path_colour(i), 0.5));
}

// The box, median, whiskers and outliers of `s` at `x`, in entry i's colour.
void draw_box(Chart& chart, double x, const ValueSummary& s, std::size_t i) {
  const double half = 0.3;
  svg::Drawing& d = chart.drawing();
  d.polygon({{chart.at(x - half, s.q1), chart.at(x + half, s.q1), chart.at(x + half, s.q3), chart.at(x - half, s.q3)}},
            svg::filled(theme::path_colour(i), 0.25, theme::path_colour(i), 1.5));
  d.segments({{chart.at(x - half, s.median), chart.at(x + half, s.median)},
              {chart.at(x, s.q3), chart.at(x, s.whisker_high)},
              {chart.at(x, s.q1), chart.at(x, s.whisker_low)},
              {chart.at(x - half / 2, s.whisker_high), chart.at(x + half / 2, s.whisker_high)},
              {chart.at(x - half / 2, s.whisker_low), chart.at(x + half / 2, s.whisker_low)}},
             line(i, 1.5));
  std::vector<Point2> outliers;
  for (double v : s.outliers)
    if (std::isfinite(v)) outliers.push_back(chart.at(x, v));
  d.points(outliers, 2.5, svg::filled("#ffffff", 1, theme::path_colour(i), 1));
}

// An entry's name under its box at `x`, slanted so that long names do not collide.
// The room under the frame, in the chart's units, for labels slanted as draw_box_label slants them:
// 14 px down to the baseline's end, then sin 35° of the longest label's length (11 px glyphs, 0.6
// em wide), so that a frame with short names leaves no empty band below them.
double room_for_slanted(const std::vector<std::string>& labels) {
  std::size_t longest = 0;
  for (const std::string& label : labels) longest = std::max(longest, label.size());
  const double px = 14 + std::sin(35 * 3.14159265358979 / 180) * 0.6 * 11 * static_cast<double>(longest) + 8;
  return std::max(0.12, px / kPixelsPerUnit);
}

void draw_box_label(Chart& chart, double x, const std::string& label) {
  svg::Drawing& d = chart.drawing();
  const Point2 foot = d.to_screen({chart.to_x(x), 0});
  const std::string at_x = svg::format_number(foot.x), at_y = svg::format_number(foot.y + 14);
  d.raw("<text x=\"" + at_x + "\" y=\"" + at_y + "\" font-size=\"11\" fill=\"#222\" text-anchor=\"end\" " +
        "transform=\"rotate(-35 " + at_x + " " + at_y + ")\">" + svg::escape_xml(label) + "</text>\n");
}

}  // namespace

double PlotAxis::to_unit(double value) const {
  if (!log) return (value - lo) / (hi - lo);
  return (std::log10(std::max(value, lo)) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
}

std::vector<double> PlotAxis::ticks() const {
  if (!(lo < hi)) return {};  // no room for a tick, and no step to count them by
  return log ? log_ticks(lo, hi) : nice_ticks(lo, hi);
}

svg::Drawing success_rate_plot(const Experiment& e, std::size_t problem,
                               const std::vector<CellStatistics>& statistics) {
  std::vector<double> times;
  for (const CellStatistics& s : statistics)
    times.insert(times.end(), s.first_solutions.begin(), s.first_solutions.end());
  const PlotAxis x = success_axis(times, e.time_limit);
  Chart chart(x, {0, 100, false}, title_of(e, problem, "success rate"), time_name(x, e.time_limit), "solved (%)");
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    chart.drawing().polyline(success_steps(chart, statistics[i]), line(i));
    chart.drawing().legend(e.planners[i].name, line(i), svg::Swatch::line);
  }
  return std::move(chart.drawing());
}

std::optional<svg::Drawing> cost_over_time_plot(const Experiment& e, std::size_t problem,
                                                const std::vector<CellStatistics>& statistics) {
  std::vector<double> drawn;  // the quartiles and medians, the y axis' extent
  bool any = false;
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    if (!e.planners[i].anytime) continue;
    any = true;
    for (const ValueSummary& c : statistics[i].cost_at) drawn.insert(drawn.end(), {c.q1, c.median, c.q3});
  }
  if (!any || e.cost_times.empty()) return std::nullopt;
  const PlotAxis x = spans_decade(e.cost_times) ? log_fit(e.cost_times) : PlotAxis{0, e.time_limit, false};
  Chart chart(x, linear_fit(drawn, false), title_of(e, problem, "best cost, median and quartiles"),
              time_name(x, e.time_limit), "best cost (path length)");
  for (std::size_t i = 0; i < statistics.size(); ++i)
    if (e.planners[i].anytime) {
      draw_costs(chart, e.cost_times, statistics[i].cost_at, i);
      chart.drawing().legend(e.planners[i].name, line(i), svg::Swatch::line);
    }
  return std::move(chart.drawing());
}

svg::Drawing box_plot(const Experiment& e, std::size_t problem, const std::vector<CellStatistics>& statistics,
                      BoxPlotOf of) {
  const auto summary = [&](const CellStatistics& s) -> const ValueSummary& {
    return of == BoxPlotOf::time ? s.time : s.length;
  };
  // The frame fits what is drawn: the whiskers' ends and the outliers.
  std::vector<double> drawn;
  for (const CellStatistics& s : statistics)
    if (summary(s).count) {
      drawn.insert(drawn.end(), {summary(s).whisker_low, summary(s).whisker_high});
      drawn.insert(drawn.end(), summary(s).outliers.begin(), summary(s).outliers.end());
    }
  const PlotAxis y = fit(drawn, of == BoxPlotOf::time, true);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < statistics.size(); ++i)
    labels.push_back(e.planners[i].name + (summary(statistics[i]).count ? "" : " (none)"));
  const std::size_t n = std::max<std::size_t>(statistics.size(), 1);
  Chart chart({0, static_cast<double>(n), false}, y,
              title_of(e, problem, of == BoxPlotOf::time ? "time per run" : "length of the solved runs"), "",
              of == BoxPlotOf::time ? time_name(y, e.time_limit) : "length", room_for_slanted(labels));
  for (std::size_t i = 0; i < statistics.size(); ++i) {
    const double x = static_cast<double>(i) + 0.5;
    const ValueSummary& s = summary(statistics[i]);
    if (s.count) draw_box(chart, x, s, i);
    draw_box_label(chart, x, labels[i]);
  }
  return std::move(chart.drawing());
}

}  // namespace polyplan
