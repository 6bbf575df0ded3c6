#include <polyplan/homotopy/h_signature.hpp>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace polyplan {

void multiply(Word& word, const Word& letters) {
  for (const int letter : letters) {
    if (!word.empty() && word.back() == -letter) word.pop_back();
    else word.push_back(letter);
  }
}

Word inverse(const Word& word) {
  Word out(word.rbegin(), word.rend());
  for (int& letter : out) letter = -letter;
  return out;
}

std::string word_text(const Word& word) {
  std::string out;
  for (const int letter : word)
    out += (out.empty() ? "t" : " t") + std::to_string(std::abs(letter)) + (letter < 0 ? "'" : "");
  return out;
}

namespace {

// Where the horizontal line at height y crosses the ring's edges (no vertex lies on it).
void crossings_at(const Ring& ring, const Rational& y, std::vector<Rational>& out) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint &a = ring[i], &b = ring[(i + 1) % ring.size()];
    if ((a.y < y) != (b.y < y)) out.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
  }
}

// A point strictly inside the C-obstacle whose outer ring is `ring`, in no free pocket within it
// (blocked, by the exact C-space), whose vertical line meets none of `xs`: on a horizontal line
// midway between two consecutive vertex heights of all the boundary (`rings`), so that it crosses
// edges only, in a piece between two crossings that lies inside the ring, at its middle, then a
// third, a ninth, ... of it.
ExactPoint inside_point(const CSpace& cspace, const Ring& ring, const std::vector<const Ring*>& rings,
                        const std::set<Rational>& xs) {
  std::set<Rational> heights;
  for (const Ring* r : rings)
    for (const ExactPoint& p : *r) heights.insert(p.y);
  Rational low = ring.front().y, high = low;
  for (const ExactPoint& p : ring) low = std::min(low, p.y), high = std::max(high, p.y);
  for (auto h = heights.lower_bound(low); h != heights.end() && *h < high; ++h) {
    const Rational y = (*h + *std::next(h)) / 2;
    std::vector<Rational> all, own;
    for (const Ring* r : rings) crossings_at(*r, y, all);
    crossings_at(ring, y, own);
    std::sort(all.begin(), all.end());
    for (std::size_t k = 0; k + 1 < all.size(); ++k) {
      const Rational left = all[k], width = all[k + 1] - all[k];
      if (width == 0) continue;
      Rational x = left + width / 2, step = width / 3;
      for (int tries = 0; tries < 64 && xs.count(x); ++tries) x = left + step, step /= 3;
      const auto left_of = std::count_if(own.begin(), own.end(), [&](const Rational& c) { return c < x; });
      if (left_of % 2 == 1 && !xs.count(x) && cspace.locate({x, y}).kind == Location::Kind::blocked) return {x, y};
    }
  }
  throw std::logic_error("h-signature: no point inside the C-obstacle round " + to_string(ring.front()));
}

}  // namespace

HSignature::HSignature(const CSpace& cspace) {
  std::set<Rational> xs;  // every vertex's x, and each chosen ray's
  const auto& components = cspace.free_components();
  bool first = true;
  const auto note = [&](const ExactPoint& p) {
    xs.insert(p.x);
    if (first || p.y > top_) top_ = p.y, first = false;
  };
  for (const FreeComponent& c : components) {
    for (const ExactPoint& p : c.outer) note(p);
    for (const Ring& h : c.holes)
      for (const ExactPoint& p : h) note(p);
  }
  std::vector<const Ring*> rings;
  for (const FreeComponent& c : components) {
    if (!c.outer.empty()) rings.push_back(&c.outer);
    for (const Ring& h : c.holes) rings.push_back(&h);
  }
  for (std::size_t c = 0; c < components.size(); ++c)
    for (std::size_t h = 0; h < components[c].holes.size(); ++h) {
      // A hole of the free space is a C-obstacle's outer ring (its own holes are other components).
      const ExactPoint origin = inside_point(cspace, components[c].holes[h], rings, xs);
      xs.insert(origin.x);
      rays_.push_back({origin, c, h});
    }
}

Word HSignature::segment(const ExactPoint& a, const ExactPoint& b) const {
  // Crossings ordered along a → b by their parameter t = (x − a.x) / (b.x − a.x).
  std::vector<std::pair<Rational, int>> crossings;
  for (std::size_t i = 0; i < rays_.size(); ++i) {
    const Rational& rx = rays_[i].origin.x;
    const bool a_left = a.x < rx, b_left = b.x < rx;
    if (a_left == b_left) continue;
    const Rational t = (rx - a.x) / (b.x - a.x);
    if (!(a.y + t * (b.y - a.y) > rays_[i].origin.y)) continue;  // below the ray's origin: no ray there
    const int letter = static_cast<int>(i) + 1;
    crossings.emplace_back(t, a_left ? letter : -letter);
  }
  std::sort(crossings.begin(), crossings.end());
  Word word;
  for (const auto& [t, letter] : crossings) multiply(word, {letter});
  return word;
}

std::vector<std::vector<ExactPoint>> HSignature::ray_segments() const {
  std::vector<std::vector<ExactPoint>> out;
  for (const HomotopyRay& ray : rays_)
    out.push_back({ray.origin, {ray.origin.x, std::max(top_, Rational(ray.origin.y + 1))}});
  return out;
}

Word HSignature::polyline(const std::vector<ExactPoint>& path) const {
  Word word;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) multiply(word, segment(path[i], path[i + 1]));
  return word;
}

}  // namespace polyplan
