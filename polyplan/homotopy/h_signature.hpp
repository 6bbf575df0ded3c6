#pragma once
// Homotopy classes of paths in a translating robot's free space, as words (Bhattacharya, Kumar &
// Likhachev's h-signature; the course's sampling-planner homework): each hole of the free space (a C-obstacle the free
// space goes round) gets a reference point strictly inside it and a ray from there straight up; a path reads a letter
// each time it crosses a ray, t_i from left to right and t_i' from right to left, and its word, reduced in the free
// group (adjacent t_i t_i' cancel), names its homotopy class among paths with the same ends. The reduced word is a
// homotopy invariant, not only a homology one: the commutator loop t1 t2 t1' t2' round two holes is not trivial here,
// where a winding-number vector (homology) would call it so. The rays are vertical and no two share an x, so cutting
// the plane along them leaves simply connected pieces: the word of a path is a complete invariant of its class.
//
// Exact: a point's side of a ray is x < ray x (left) or not (right), so a path vertex on a ray's
// line is on its right, consistently, and the word of a concatenation is the product of the
// words. The reference point is chosen (exactly) so that no vertex of any C-obstacle or wall lies on
// any ray's line.
#include <polyplan/geometry/cspace.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

// A reduced word: letters ±(i + 1) for the ray of hole i, + for left-to-right crossings.
using Word = std::vector<int>;

// Appends `letters` to `word`, cancelling as it goes: the product in the free group.
void multiply(Word& word, const Word& letters);
Word inverse(const Word& word);
// "t1 t2' t1" (holes numbered from 1); "" for the empty word.
std::string word_text(const Word& word);

struct HomotopyRay {
  ExactPoint origin;                    // strictly inside the hole
  std::size_t component = 0, hole = 0;  // which FreeComponent's holes[...]
};

class HSignature {
 public:
  explicit HSignature(const CSpace& cspace);

  const std::vector<HomotopyRay>& rays() const { return rays_; }
  // The (reduced) word of the straight motion a → b, and of a polyline.
  Word segment(const ExactPoint& a, const ExactPoint& b) const;
  Word polyline(const std::vector<ExactPoint>& path) const;
  // Each ray as a segment from its origin up to the height of the highest boundary vertex: what a
  // picture draws.
  std::vector<std::vector<ExactPoint>> ray_segments() const;

 private:
  std::vector<HomotopyRay> rays_;
  Rational top_ = 0;
};

}  // namespace polyplan
