#pragma once
// A stored Roadmap under an incremental search (search/incremental_search.hpp): edge lengths as
// exact integers, so that the costs LPA* and D* Lite report equal a fresh search's to the last unit
// whatever the order they were summed in, and edges whose cost the caller changes.
//
// A length is counted in units of 2^-24 (about 6e-8): an edge's length rounded *up* to a unit, the
// heuristic's straight-line distance rounded *down* and less a relative 1e-12 (std::hypot's error
// is within an ulp, 1.1e-16 relative, on each side of the triangle inequality), so the heuristic
// stays consistent: floor(d(u,t)) <= ceil(d(u,v)) + floor(d(v,t)) whenever d(u,t) <= d(u,v) + d(v,t).
#include <polyplan/search/roadmap.hpp>

#include <cmath>
#include <compare>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace polyplan {

class ScaledLength {
 public:
  static constexpr double units_per_length = 16777216.0;  // 2^24
  constexpr ScaledLength() = default;
  constexpr explicit ScaledLength(std::int64_t units) : units_(units) {}
  static constexpr ScaledLength infinity() { return ScaledLength(infinite_units); }
  // The length rounded up (edges) or down (lower bounds) to a unit; infinity for an infinite one.
  static ScaledLength at_least(double length) { return from(std::ceil(length * units_per_length)); }
  static ScaledLength at_most(double length) { return from(std::floor(length * units_per_length)); }

  constexpr std::int64_t units() const { return units_; }
  double to_double() const {
    return units_ == infinite_units ? std::numeric_limits<double>::infinity()
                                    : static_cast<double>(units_) / units_per_length;
  }
  friend constexpr ScaledLength operator+(ScaledLength a, ScaledLength b) {
    if (a.units_ == infinite_units || b.units_ == infinite_units) return infinity();
    return ScaledLength(a.units_ + b.units_);
  }
  friend constexpr bool operator==(ScaledLength, ScaledLength) = default;
  friend constexpr auto operator<=>(ScaledLength, ScaledLength) = default;

 private:
  // Sums of finite lengths stay far below it: 2^62 units is 2.7e11 length units.
  static constexpr std::int64_t infinite_units = std::numeric_limits<std::int64_t>::max();
  static ScaledLength from(double units) {
    return units < 0x1p62 ? ScaledLength(static_cast<std::int64_t>(units)) : infinity();
  }
  std::int64_t units_ = 0;
};

// The edges' lengths, or the cost set for a move (either direction on its own). A cost set must
// be at least the edge's length (or infinity: blocked), or the heuristic would overestimate.
// Vertex ids below 2^32. Looking an edge up costs the degree of its source (adjacency lists).
class RoadmapCosts {
 public:
  explicit RoadmapCosts(const Roadmap& roadmap) : roadmap_(&roadmap) {}
  ScaledLength operator()(RoadmapVertexId from, RoadmapVertexId to) const {
    if (!set_.empty())
      if (const auto it = set_.find(key(from, to)); it != set_.end()) return it->second;
    const auto [edge, exists] = boost::edge(from, to, *roadmap_);
    return exists ? ScaledLength::at_least((*roadmap_)[edge].length) : ScaledLength::infinity();
  }
  void set(RoadmapVertexId from, RoadmapVertexId to, ScaledLength cost) { set_[key(from, to)] = cost; }

 private:
  static std::uint64_t key(RoadmapVertexId from, RoadmapVertexId to) {
    return (static_cast<std::uint64_t>(from) << 32) | static_cast<std::uint64_t>(to);
  }
  const Roadmap* roadmap_;
  std::unordered_map<std::uint64_t, ScaledLength> set_;
};

// The straight-line distance, a consistent lower bound of any cost at least the edges' lengths.
struct RoadmapDistance {
  const Roadmap* roadmap;
  ScaledLength operator()(RoadmapVertexId a, RoadmapVertexId b) const {
    const RoadmapVertex &p = (*roadmap)[a], &q = (*roadmap)[b];
    return ScaledLength::at_most(std::hypot(p.x - q.x, p.y - q.y) * (1 - 1e-12));
  }
};

}  // namespace polyplan
