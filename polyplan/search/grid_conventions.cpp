#include <polyplan/search/grid_conventions.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <numeric>

namespace polyplan {
namespace {

// A number's value when it is one whose text is a whole number of millionths or fewer decimals:
// n / 10^k reduced, k <= 6 (the double read from the text, scaled until it is whole).
std::optional<DiagonalCost> exact_fraction(double value) {
  std::int64_t scale = 1;
  for (int decimals = 0; decimals <= 6; ++decimals, scale *= 10) {
    const double scaled = value * static_cast<double>(scale);
    if (std::round(scaled) != scaled || std::round(scaled) / static_cast<double>(scale) != value) continue;
    const auto n = static_cast<std::int64_t>(scaled), g = std::gcd(n, scale);
    return DiagonalCost{n / g, scale / g};
  }
  return std::nullopt;
}

}  // namespace

double DiagonalCost::value() const {
  return is_sqrt2() ? std::sqrt(2.0) : static_cast<double>(numerator) / static_cast<double>(denominator);
}

std::string DiagonalCost::text() const {
  if (is_sqrt2()) return "sqrt2";
  const double v = value();
  std::string s(32, '\0');
  const auto [end, ec] = std::to_chars(s.data(), s.data() + s.size(), v);
  s.resize(static_cast<std::size_t>(end - s.data()));
  return s;
}

std::optional<DiagonalCost> parse_diagonal_cost(std::string_view text, std::string& why) {
  if (text == "sqrt2" || text == "√2" || text == "sqrt(2)") return DiagonalCost{};
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    why = "expected sqrt2 or a number of at least 1";
    return std::nullopt;
  }
  if (value == std::sqrt(2.0)) return DiagonalCost{};
  // Below 1 a diagonal would be cheaper than a straight move; above 1000 the exact sums could
  // overflow on a large map.
  if (!(value >= 1) || value > 1000) {
    why = "expected sqrt2 or a number in [1, 1000] (a diagonal move is never cheaper than a straight one)";
    return std::nullopt;
  }
  if (auto exact = exact_fraction(value)) return exact;
  why = "expected sqrt2 or a number with at most 6 decimals (costs are kept as exact fractions)";
  return std::nullopt;
}

OctileLength GridConventions::straight_step() const {
  return {diagonal_cost.is_sqrt2() ? 1 : diagonal_cost.denominator, 0};
}

OctileLength GridConventions::diagonal_step() const {
  return diagonal_cost.is_sqrt2() ? OctileLength(0, 1) : OctileLength(diagonal_cost.numerator, 0);
}

OctileLength GridConventions::distance(std::int64_t dx, std::int64_t dy) const {
  dx = std::abs(dx);
  dy = std::abs(dy);
  const std::int64_t straight = straight_step().straight();
  // Two straight moves beat a diagonal dearer than 2: then the grid is as good as 4-connected.
  const bool diagonals_help = connectivity == Connectivity::full &&
                              (diagonal_cost.is_sqrt2() || diagonal_cost.numerator <= 2 * diagonal_cost.denominator);
  if (!diagonals_help) return {(dx + dy) * straight, 0};
  const std::int64_t diagonal = std::min(dx, dy), rest = std::max(dx, dy) - diagonal;
  const OctileLength d = diagonal_step();
  return OctileLength(rest * straight + diagonal * d.straight(), diagonal * d.diagonal());
}

double GridConventions::in_cells(const OctileLength& cost) const {
  return cost.to_double() / static_cast<double>(straight_step().straight());
}

void set_diagonals(GridGraph& graph, const GridConventions& conventions) {
  if (conventions.connectivity == Connectivity::axis_aligned) return;
  if (conventions.diagonal_cost.is_sqrt2() && !conventions.corner_cutting) return;
  graph.set_diagonals(conventions.diagonal_cost.is_sqrt2() ? std::nullopt
                                                           : std::optional<double>(conventions.diagonal_cost.value()),
                      conventions.corner_cutting);
}

GridMetric square_grid_metric(const GridGraph& graph) {
  if (graph.connectivity() == Connectivity::axis_aligned) return GridMetric::sum_of_axes;
  return graph.diagonal_cost().value_or(0) >= 2 ? GridMetric::sum_of_axes : GridMetric::octile;
}

std::string GridConventions::text(const OctileLength& cost) const {
  const std::int64_t unit = straight_step().straight();
  if (cost.is_infinite() || unit == 1) return cost.to_string();
  const std::int64_t g = std::gcd(cost.straight(), unit);
  return std::to_string(cost.straight() / g) + (unit / g == 1 ? "" : "/" + std::to_string(unit / g));
}

}  // namespace polyplan
