// The extended-precision reference for polyplan's Dubins lengths where OMPL's is none
// (tests/data/car/dubins_extended.csv). In 27 degenerate cases of tests/data/car/ompl_dubins.csv
// — a goal 1e-9 behind, left or right of the start with the same heading, a heading change of
// +-1e-9 rad on the spot (or across the -pi/pi seam) — OMPL's path does not reach its goal (it
// drives a straight of 1e-9 or nothing where the car must loop), so OMPL's length checks nothing.
// This program computes the shortest path that does reach it, in 256-bit MPFR arithmetic, so
// that offsets of 1e-9 are resolved exactly.
//
//   g++ -std=c++20 -O2 bench/dubins_extended_reference.cpp -lmpfr -lgmp -o dubins_extended_reference
//   dubins_extended_reference [SOURCE_DIR]   (default: the current directory, the repository root)
//
// reads SOURCE_DIR/tests/data/car/ompl_dubins.csv and steering_cases.txt, picks the rows by their
// names (the list is in dubins_misses below: this program is the one place that selects them),
// and writes SOURCE_DIR/tests/data/car/dubins_extended.csv: a '#' comment line, a header line,
// and rows name,x0,y0,theta0,x1,y1,theta1,radius,length,word. The inputs are the CSV's doubles
// (printed round-trip), each converted exactly to 256 bits; length has 17 significant digits of
// the 256-bit value; word is the shortest word, or the words tied with it ("LSL/RSR": equal
// lengths in exact arithmetic, to 1e-60).
//
// Every one of the six words (LSL, RSR, LSR, RSL, RLR, LRL; the formulas of Shkel and Lumelsky
// 2001, in the normalised frame d = D/R, alpha, beta) is driven segment by segment from the start
// pose, again in 256 bits, and kept only if it ends on the goal: position to 1e-30 times
// max(1, R, |coordinates|), heading to 1e-30 rad mod 2 pi. The shortest word kept is the
// reference. A segment within 1e-60 of 0 or 2 pi (mod 2 pi) is 0: 256 bits round an exact 0 to
// about 1e-75, while the true segments of these inputs (doubles, offsets of 1e-9) are far larger.
//
// Reaching exactly is the right test for these rows only: their offsets (1e-9) are far above the
// doubles' rounding and the tests' tolerances (1e-12). Where a goal is off its intended pose only
// by the rounding of the doubles (heading pi to -pi: the double pi is 1.2e-16 short of pi; a goal
// on a circle, rounded), exact arithmetic demands a loop where the tests, reaching to 1e-12,
// rightly take OMPL's length; so the rows are picked by name, not by running every row.
//
// Independent of polyplan's code: it includes no polyplan header and links no polyplan library,
// so the reference does not share the code it checks (nor OMPL's: the formulas are written here).
#include <mpfr.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr mpfr_prec_t bits = 256;
constexpr mpfr_rnd_t rnd = MPFR_RNDN;

// A 256-bit real, with the operators the formulas need (each rounds to nearest).
class Real {
 public:
  Real() {
    mpfr_init2(v_, bits);
    mpfr_set_zero(v_, 1);
  }
  Real(double d) {
    mpfr_init2(v_, bits);
    mpfr_set_d(v_, d, rnd);
  }  // exact: 53 bits fit in 256
  Real(const Real& o) {
    mpfr_init2(v_, bits);
    mpfr_set(v_, o.v_, rnd);
  }
  Real& operator=(const Real& o) {
    mpfr_set(v_, o.v_, rnd);
    return *this;
  }
  ~Real() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

  template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)>
  static Real binary(const Real& a, const Real& b) {
    Real r;
    F(r.v_, a.v_, b.v_, rnd);
    return r;
  }
  template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)>
  static Real unary(const Real& a) {
    Real r;
    F(r.v_, a.v_, rnd);
    return r;
  }

 private:
  mpfr_t v_;
};

Real operator+(const Real& a, const Real& b) { return Real::binary<mpfr_add>(a, b); }
Real operator-(const Real& a, const Real& b) { return Real::binary<mpfr_sub>(a, b); }
Real operator*(const Real& a, const Real& b) { return Real::binary<mpfr_mul>(a, b); }
Real operator/(const Real& a, const Real& b) { return Real::binary<mpfr_div>(a, b); }
Real operator-(const Real& a) { return Real::unary<mpfr_neg>(a); }
bool operator<(const Real& a, const Real& b) { return mpfr_less_p(a.get(), b.get()); }
Real sin(const Real& a) { return Real::unary<mpfr_sin>(a); }
Real cos(const Real& a) { return Real::unary<mpfr_cos>(a); }
Real sqrt(const Real& a) { return Real::unary<mpfr_sqrt>(a); }
Real acos(const Real& a) { return Real::unary<mpfr_acos>(a); }
Real abs(const Real& a) { return Real::unary<mpfr_abs>(a); }
Real atan2(const Real& y, const Real& x) { return Real::binary<mpfr_atan2>(y, x); }
Real hypot(const Real& a, const Real& b) { return Real::binary<mpfr_hypot>(a, b); }
Real max(const Real& a, const Real& b) { return a < b ? b : a; }

Real pi() {
  Real r;
  mpfr_const_pi(r.get(), rnd);
  return r;
}
Real two_pi() { return Real(2) * pi(); }

Real parse(const char* text) {
  Real r;
  mpfr_set_str(r.get(), text, 10, rnd);
  return r;
}
const Real rounding_zero = parse("1e-60");

// x mod 2 pi in [0, 2 pi), an exact 0 that rounding put just below 2 pi or just above 0 being 0.
Real mod2pi(const Real& x) {
  Real r = Real::binary<mpfr_fmod>(x, two_pi());
  if (r < Real(0)) r = r + two_pi();
  if (r < rounding_zero || two_pi() - r < rounding_zero) return Real(0);
  return r;
}

// x wrapped to [-pi, pi]: how far apart two headings are.
Real wrap(const Real& x) { return Real::binary<mpfr_remainder>(x, two_pi()); }

std::string text(const Real& x, int digits) {
  char buffer[128];
  mpfr_snprintf(buffer, sizeof buffer, "%.*Rg", digits, x.get());
  return buffer;
}

struct Pose {
  Real x, y, theta;
};

// A word: its letters and its three segments, each in turning radii (t and q arcs in radians, p
// an arc or a straight).
struct Word {
  std::string letters;
  Real t, p, q;
  Real length() const { return t + p + q; }
};

// The six words that exist for the normalised pose pair (Shkel and Lumelsky, "Classification of
// the Dubins set", 2001): d the distance over R, alpha and beta the headings from the line joining
// the two positions.
std::vector<Word> dubins_words(const Real& d, const Real& alpha, const Real& beta) {
  const Real sa = sin(alpha), sb = sin(beta), ca = cos(alpha), cb = cos(beta), cab = cos(alpha - beta);
  const Real two(2), zero(0), one(1);
  std::vector<Word> words;
  {  // LSL
    const Real tmp = two + d * d - two * cab + two * d * (sa - sb);
    if (!(tmp < zero)) {
      const Real theta = atan2(cb - ca, d + sa - sb);
      words.push_back({"LSL", mod2pi(theta - alpha), sqrt(tmp), mod2pi(beta - theta)});
    }
  }
  {  // RSR
    const Real tmp = two + d * d - two * cab + two * d * (sb - sa);
    if (!(tmp < zero)) {
      const Real theta = atan2(ca - cb, d - sa + sb);
      words.push_back({"RSR", mod2pi(alpha - theta), sqrt(tmp), mod2pi(theta - beta)});
    }
  }
  {  // LSR
    const Real tmp = d * d - two + two * cab + two * d * (sa + sb);
    if (!(tmp < zero)) {
      const Real p = sqrt(tmp);
      const Real theta = atan2(-ca - cb, d + sa + sb) - atan2(-two, p);
      words.push_back({"LSR", mod2pi(theta - alpha), p, mod2pi(theta - beta)});
    }
  }
  {  // RSL
    const Real tmp = d * d - two + two * cab - two * d * (sa + sb);
    if (!(tmp < zero)) {
      const Real p = sqrt(tmp);
      const Real theta = atan2(ca + cb, d - sa - sb) - atan2(two, p);
      words.push_back({"RSL", mod2pi(alpha - theta), p, mod2pi(beta - theta)});
    }
  }
  {  // RLR: the middle arc longer than pi (Dubins: a shortest CCC's is)
    const Real tmp = (Real(6) - d * d + two * cab + two * d * (sa - sb)) / Real(8);
    if (abs(tmp) < one || mpfr_equal_p(abs(tmp).get(), one.get())) {
      const Real p = mod2pi(two_pi() - acos(tmp));
      const Real theta = atan2(ca - cb, d - sa + sb);
      const Real t = mod2pi(alpha - theta + p / two);
      words.push_back({"RLR", t, p, mod2pi(alpha - beta - t + p)});
    }
  }
  {  // LRL
    const Real tmp = (Real(6) - d * d + two * cab + two * d * (sb - sa)) / Real(8);
    if (abs(tmp) < one || mpfr_equal_p(abs(tmp).get(), one.get())) {
      const Real p = mod2pi(two_pi() - acos(tmp));
      const Real theta = atan2(cb - ca, d + sa - sb);
      const Real t = mod2pi(theta - alpha + p / two);
      words.push_back({"LRL", t, p, mod2pi(beta - alpha - t + p)});
    }
  }
  return words;
}

// Drives `length` turning radii of the letter from `pose`: an arc about the centre R to the left
// (L) or right (R), or a straight (S).
Pose drive(const Pose& pose, char letter, const Real& length, const Real& radius) {
  if (letter == 'S')
    return {pose.x + radius * length * cos(pose.theta), pose.y + radius * length * sin(pose.theta), pose.theta};
  const Real side = letter == 'L' ? Real(1) : Real(-1);
  const Real theta = pose.theta + side * length;
  // The centre is at pose + side * R * (-sin, cos); the car at centre + side * R * (sin, -cos) of
  // the new heading.
  return {pose.x + side * radius * (sin(theta) - sin(pose.theta)),
          pose.y + side * radius * (cos(pose.theta) - cos(theta)), theta};
}

// Whether the word, driven from `from`, ends on `to`.
bool reaches(const Word& word, const Pose& from, const Pose& to, const Real& radius) {
  Pose pose = drive(from, word.letters[0], word.t, radius);
  pose = drive(pose, word.letters[1], word.p, radius);
  pose = drive(pose, word.letters[2], word.q, radius);
  const Real scale = max(max(max(Real(1), radius), max(abs(from.x), abs(from.y))), max(abs(to.x), abs(to.y)));
  const Real tolerance = parse("1e-30");
  return hypot(pose.x - to.x, pose.y - to.y) < tolerance * scale && abs(wrap(pose.theta - to.theta)) < tolerance;
}

struct Answer {
  Real length;  // in length units (turning radii times R)
  std::string words;
};

// The shortest word that reaches the goal, with any tied with it.
std::optional<Answer> shortest(const Pose& from, const Pose& to, const Real& radius) {
  const Real dx = to.x - from.x, dy = to.y - from.y;
  const Real phi = atan2(dy, dx);  // 0 for a goal on the start: then alpha, beta are the headings
  const Real d = hypot(dx, dy) / radius;
  const std::vector<Word> words = dubins_words(d, mod2pi(from.theta - phi), mod2pi(to.theta - phi));
  std::optional<Answer> best;
  for (const Word& w : words) {
    const bool ok = reaches(w, from, to, radius);
    std::cerr << "  " << w.letters << " " << text(w.length() * radius, 25) << (ok ? "" : "  (misses the goal)") << "\n";
    if (!ok) continue;
    const Real length = w.length() * radius;
    if (!best || length < best->length - rounding_zero) {
      best = Answer{length, w.letters};
    } else if (abs(length - best->length) < rounding_zero) {
      best->words += "/" + w.letters;
    }
  }
  return best;
}

// The cases where OMPL's Dubins path misses its goal (tests/car/steering_reference_test.cpp
// names the same 27): for each radius, a goal 1e-9 behind, left or right with the same heading (0
// or 0.7 rad), and a turn of +-1e-9 rad on the spot or across the -pi/pi seam.
std::vector<std::string> dubins_misses() {
  std::vector<std::string> names;
  for (const char* radius : {"r0.25", "r1", "r7.5"}) {
    for (const char* side : {"behind", "left", "right"})
      for (const char* heading : {"h0", "h0.7"})
        names.push_back(std::string("tiny_") + side + "_same_" + heading + "_" + radius);
    for (const char* turn : {"plus", "minus"}) names.push_back(std::string("tiny_turn_") + turn + "_" + radius);
    names.push_back(std::string("tiny_seam_turn_") + radius);
  }
  return names;
}

// The CSV's data rows (not the comment, not the header), each its fields as printed.
std::vector<std::vector<std::string>> read_rows(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::vector<std::string> fields;
    std::istringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

std::map<std::string, std::size_t> rows_by_name(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::map<std::string, std::size_t> rows;
  std::size_t row;
  std::string name;
  while (in >> row >> name) rows[name] = row;
  return rows;
}

// A field as the double it prints (round-trip), then that double exactly.
double field(const std::string& f) {
  char* end = nullptr;
  const double d = std::strtod(f.c_str(), &end);
  if (end == f.c_str() || *end != '\0') throw std::runtime_error("not a number: " + f);
  return d;
}

std::string round_trip(double d) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", d);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string dir = std::string(argc > 1 ? argv[1] : ".") + "/tests/data/car/";
  const auto rows = read_rows(dir + "ompl_dubins.csv");
  const auto names = rows_by_name(dir + "steering_cases.txt");
  std::ofstream out(dir + "dubins_extended.csv");
  if (!out) throw std::runtime_error("cannot write " + dir + "dubins_extended.csv");
  out << "# made by bench/dubins_extended_reference.cpp (g++ -std=c++20 -O2 bench/dubins_extended_reference.cpp -lmpfr "
         "-lgmp"
         " -o dubins_extended_reference; dubins_extended_reference, run in the repository root) with MPFR "
      << mpfr_get_version() << " at " << bits
      << " bits, independent of polyplan's code: the shortest Dubins path that reaches the goal (each of the six words "
         "driven"
         " from the start in 256 bits; kept if it ends within 1e-30) for the rows of ompl_dubins.csv where OMPL's path "
         "misses"
         " its goal, named as in steering_cases.txt; inputs the CSV's doubles exactly; length to 17 significant "
         "digits; word"
         " the shortest word (tied words, equal to 1e-60, joined by /)\n";
  out << "name,x0,y0,theta0,x1,y1,theta1,radius,length,word\n";
  for (const std::string& name : dubins_misses()) {
    if (!names.count(name)) throw std::runtime_error("no case named " + name + " in steering_cases.txt");
    const std::vector<std::string>& f = rows.at(names.at(name));
    double in[7];
    for (int i = 0; i < 7; ++i) in[i] = field(f.at(i));
    const Pose from{in[0], in[1], in[2]}, to{in[3], in[4], in[5]};
    const Real radius(in[6]);
    std::cerr << name << " (row " << names.at(name) << ")\n";
    const std::optional<Answer> best = shortest(from, to, radius);
    if (!best) throw std::runtime_error("no word reaches the goal of " + name);
    out << name;
    for (double d : in) out << "," << round_trip(d);
    out << "," << text(best->length, 17) << "," << best->words << "\n";
    std::cerr << "  shortest " << best->words << " " << text(best->length, 25) << "\n";
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "dubins_extended_reference: " << e.what() << "\n";
  return 1;
}
