#include <polyplan/geometry/rotation.hpp>

#include <CGAL/Gmpz.h>
#include <CGAL/rational_rotation.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace polyplan {
namespace {

constexpr double pi = 3.14159265358979323846;

Rational to_rational(const CGAL::Gmpz& n) { return Rational(mpz_class(n.mpz())); }

}  // namespace

Rotation exact_rotation(double degrees) {
  if (!std::isfinite(degrees)) throw std::invalid_argument("an angle must be a finite number of degrees");
  double turned = std::fmod(degrees, 360.0);
  if (turned < 0) turned += 360.0;
  // Quarter turns have the exact pairs (0, ±1), (±1, 0).
  if (turned == 0) return {Rational(0), Rational(1)};
  if (turned == 90) return {Rational(1), Rational(0)};
  if (turned == 180) return {Rational(0), Rational(-1)};
  if (turned == 270) return {Rational(-1), Rational(0)};
  // CGAL bounds the error of sin (of the angle folded to [0°, 45°]); there the angle's error is at
  // most √2 times that, so half the tolerance on sin keeps the angle within the tolerance.
  CGAL::Gmpz sin, cos, den;
  const CGAL::Gmpz eps_num(1), eps_den(static_cast<long>(2 / rotation_tolerance_radians));
  CGAL::rational_rotation_approximation(turned * pi / 180, sin, cos, den, eps_num, eps_den);
  Rotation r{to_rational(sin) / to_rational(den), to_rational(cos) / to_rational(den)};
  r.sin.canonicalize();
  r.cos.canonicalize();
  if (r.sin * r.sin + r.cos * r.cos != 1) throw std::logic_error("rational_rotation_approximation: sin² + cos² is not 1");
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

std::string to_string(const Pose& pose) {
  char angle[32];
  std::snprintf(angle, sizeof angle, "%g°", pose.degrees);
  const std::string at = to_string(pose.position);
  return at.substr(0, at.size() - 1) + ", " + angle + "]";
}

}  // namespace polyplan
