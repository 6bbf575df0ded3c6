#include <polyplan/geometry/rotation.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

// The rotation by `radians`, |radians| <= π/4, from the Pythagorean triple of t = p/q ≈ tan(θ/2):
// sin = 2pq / (p² + q²), cos = (q² − p²) / (p² + q²), so sin² + cos² = 1 exactly. This is the
// construction of CGAL's rational_rotation_approximation, but p/q runs through the continued
// fraction convergents of tan(θ/2) (best approximations, about log(1/tolerance) of them) where
// CGAL walks the Stern–Brocot tree one mediant at a time: 1/2, 1/3, 1/4, ... towards a small
// angle, which took 8 s for 359.99999° and longer below.
Rotation small_rotation(double radians) {
  mpz_class p = 0, q = 1;  // no turn, when the angle is within the tolerance of none
  if (std::abs(radians) > rotation_tolerance_radians / 2) {
    // Convergents h/k of the continued fraction [a0; a1, ...] of t: h = a h' + h'', k = a k' + k''.
    mpz_class h1 = 1, k1 = 0, h2 = 0, k2 = 1;  // the two before: 1/0 and 0/1
    double rest = std::abs(std::tan(radians / 2));
    for (int term = 0; term < 64; ++term) {
      const double whole = std::floor(rest);
      const mpz_class a(whole);
      p = a * h1 + h2;
      q = a * k1 + k2;
      h2 = h1;
      k2 = k1;
      h1 = p;
      k1 = q;
      const bool close_enough =
          std::abs(2 * std::atan2(p.get_d(), q.get_d()) - std::abs(radians)) <= rotation_tolerance_radians / 2;
      if (close_enough || rest == whole) break;
      rest = 1 / (rest - whole);
    }
  }
  const mpz_class square = p * p + q * q;
  Rotation r{Rational(2 * p * q, square), Rational(q * q - p * p, square)};
  r.sin.canonicalize();
  r.cos.canonicalize();
  if (radians < 0) r.sin = -r.sin;
  return r;
}

// r turned by `quarters` quarter turns counter-clockwise, exactly.
Rotation quarter_turns(Rotation r, long quarters) {
  for (long k = 0; k < ((quarters % 4) + 4) % 4; ++k) r = {r.cos, -r.sin};
  return r;
}

}  // namespace

Rotation exact_rotation(double degrees) {
  if (!std::isfinite(degrees)) throw std::invalid_argument("an angle must be a finite number of degrees");
  // degrees = 90 k + rest with |rest| <= 45: quarter turns are exact, the rest is approximated.
  const double quarters = std::round(degrees / 90);
  const double rest = degrees - quarters * 90;  // exact: fmod-like, no rounding for |degrees| <= 1e6
  const Rotation r = quarter_turns(small_rotation(rest * pi / 180), static_cast<long>(std::fmod(quarters, 4.0)));
  if (r.sin * r.sin + r.cos * r.cos != 1) throw std::logic_error("exact_rotation: sin² + cos² is not 1");
  return r;
}

double degrees_of(const Rotation& rotation) {
  return std::atan2(to_double(rotation.sin), to_double(rotation.cos)) * 180 / pi;
}

double turn_degrees(const Rotation& from, const Rotation& to) {
  // The rotation from → to is to · from⁻¹: (sin, cos) = (s₂c₁ − c₂s₁, c₂c₁ + s₂s₁), exactly.
  const Rational s = to.sin * from.cos - to.cos * from.sin;
  const Rational c = to.cos * from.cos + to.sin * from.sin;
  return std::atan2(to_double(s), to_double(c)) * 180 / pi;
}

ExactPoint rotate(const ExactPoint& p, const Rotation& r) {
  return {r.cos * p.x - r.sin * p.y, r.sin * p.x + r.cos * p.y};
}

Robot rotated(const Robot& robot, const Rotation& rotation) {
  Robot out;
  for (const Ring& part : robot.parts) {
    Ring turned;
    turned.reserve(part.size());
    for (const ExactPoint& p : part) turned.push_back(rotate(p, rotation));
    out.parts.push_back(std::move(turned));
  }
  return out;
}

double robot_radius(const Robot& robot) {
  double radius = 0;
  for (const Ring& part : robot.parts)
    for (const ExactPoint& p : part) radius = std::max(radius, std::hypot(to_double(p.x), to_double(p.y)));
  return radius;
}

std::string angle_text(double degrees) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, degrees);  // shortest round trip
  return (error == std::errc() ? std::string(text, end) : std::to_string(degrees)) + "°";
}

std::string to_string(const Pose& pose) {
  const std::string at = to_string(pose.position);
  return at.substr(0, at.size() - 1) + ", " + angle_text(pose.degrees) + "]";
}

}  // namespace polyplan
