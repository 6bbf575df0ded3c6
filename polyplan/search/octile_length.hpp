#pragma once
// The exact length of a path on an 8-connected unit grid: a + b·√2 (a straight moves, b diagonal
// ones), or infinity (a blocked move). Sums are exact integer additions and comparisons decide the
// sign of p + q·√2 exactly (squares in 128 bits), so an incremental search's keys, its ties and the
// optimum it reports are the same as a fresh search's to the last digit — what doubles cannot
// promise when the same path is summed in another order.
#include <cmath>
#include <compare>
#include <cstdint>
#include <limits>
#include <string>

namespace polyplan {

class OctileLength {
 public:
  constexpr OctileLength() = default;  // zero
  constexpr OctileLength(std::int64_t straight, std::int64_t diagonal) : straight_(straight), diagonal_(diagonal) {}
  static constexpr OctileLength infinity() {
    OctileLength l;
    l.infinite_ = true;
    return l;
  }
  // The octile distance between cells dx and dy apart: the exact shortest length on an empty grid.
  static constexpr OctileLength octile(std::int64_t dx, std::int64_t dy) {
    dx = dx < 0 ? -dx : dx;
    dy = dy < 0 ? -dy : dy;
    return dx < dy ? OctileLength(dy - dx, dx) : OctileLength(dx - dy, dy);
  }

  constexpr bool is_infinite() const { return infinite_; }
  constexpr std::int64_t straight() const { return straight_; }
  constexpr std::int64_t diagonal() const { return diagonal_; }
  // The nearest double but for one rounding of a·1 + b·√2 (√2 itself rounded): for printing and
  // pictures, never for a decision. Infinity as +inf.
  double to_double() const {
    if (infinite_) return std::numeric_limits<double>::infinity();
    return static_cast<double>(straight_) + static_cast<double>(diagonal_) * std::sqrt(2.0);
  }
  // "3 + 2√2", "2√2", "3", "∞".
  std::string to_string() const {
    if (infinite_) return "∞";
    if (diagonal_ == 0) return std::to_string(straight_);
    const std::string root = (diagonal_ == 1 ? std::string() : std::to_string(diagonal_)) + "√2";
    return straight_ == 0 ? root : std::to_string(straight_) + " + " + root;
  }

  // Infinity absorbs: ∞ + x = ∞.
  friend constexpr OctileLength operator+(const OctileLength& x, const OctileLength& y) {
    if (x.infinite_ || y.infinite_) return infinity();
    return {x.straight_ + y.straight_, x.diagonal_ + y.diagonal_};
  }
  friend constexpr bool operator==(const OctileLength& x, const OctileLength& y) {
    if (x.infinite_ || y.infinite_) return x.infinite_ == y.infinite_;
    return x.straight_ == y.straight_ && x.diagonal_ == y.diagonal_;  // √2 is irrational
  }
  friend constexpr std::strong_ordering operator<=>(const OctileLength& x, const OctileLength& y) {
    if (x.infinite_ || y.infinite_)
      return x.infinite_ == y.infinite_ ? std::strong_ordering::equal
                                        : (x.infinite_ ? std::strong_ordering::greater : std::strong_ordering::less);
    return sign(x.straight_ - y.straight_, x.diagonal_ - y.diagonal_) <=> 0;
  }

 private:
  // The sign of p + q·√2, exactly.
  static constexpr int sign(std::int64_t p, std::int64_t q) {
    if (p >= 0 && q >= 0) return (p > 0 || q > 0) ? 1 : 0;
    if (p <= 0 && q <= 0) return -1;
    const __int128 p2 = static_cast<__int128>(p) * p, q2 = 2 * static_cast<__int128>(q) * q;
    if (p > 0) return p2 > q2 ? 1 : -1;  // q < 0: p² against 2q², never equal (√2 is irrational)
    return q2 > p2 ? 1 : -1;             // p < 0 < q
  }

  std::int64_t straight_ = 0, diagonal_ = 0;
  bool infinite_ = false;
};

}  // namespace polyplan
