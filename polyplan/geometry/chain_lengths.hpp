#pragma once
// Dijkstra's lengths and open set for searches whose paths are polylines through exact points,
// compared exactly: the classes of the homotopy planner and the tether, and the exact pass over
// a roadmap's shortest path (search/exact_shortest_path.hpp). A state is a point reached from a
// parent state by a segment; its length is kept as bounds rounded outward, and where two states'
// bounds overlap it is summed again exactly along its chain of parents (geometry/root_sum.hpp), so
// the common case costs two additions and a comparison of doubles.
#include <polyplan/geometry/root_sum.hpp>

#include <cstddef>
#include <optional>
#include <set>
#include <vector>

namespace polyplan {

class ChainLengths {
 public:
  // A way to a point: the chain to `parent` and one segment on (none: the source), its bounds.
  struct Way {
    const ExactPoint* at;
    std::optional<std::size_t> parent;
    LengthBounds bounds;
  };

  ChainLengths() = default;
  // The open set orders states through a pointer to this.
  ChainLengths(const ChainLengths&) = delete;
  ChainLengths& operator=(const ChainLengths&) = delete;

  // The source's way, and a state's way one segment (`segment` its bounds) on to `to`, which must
  // outlive this.
  static Way source(const ExactPoint& at) { return {&at, std::nullopt, {}}; }
  Way step(std::size_t from, const ExactPoint& to, const LengthBounds& segment) const {
    return {&to, from, states_[from].bounds + segment};
  }

  // A new open state reached by `way` (ids 0, 1, ... in order); an open state reached a shorter way.
  std::size_t add(const Way& way);
  void shorten(std::size_t id, const Way& way);
  // The open state shortest of all (equal lengths: the older), closed; nullopt when none is open.
  std::optional<std::size_t> close_shortest();
  bool closed(std::size_t id) const { return closed_[id]; }

  const Way& way_to(std::size_t id) const { return states_[id]; }
  std::optional<std::size_t> parent(std::size_t id) const { return states_[id].parent; }
  std::size_t size() const { return states_.size(); }

  // The sign of a's length − b's, and of a's length − c, exactly; a's length exactly.
  int compare(const Way& a, const Way& b) const;
  int compare(const Way& a, const Rational& c) const;
  RootSum exact(const Way& way) const;

 private:
  struct Shorter {
    const ChainLengths* chains;
    bool operator()(std::size_t a, std::size_t b) const;
  };
  std::vector<Way> states_;
  std::vector<bool> closed_;
  std::set<std::size_t, Shorter> open_{Shorter{this}};
};

}  // namespace polyplan
