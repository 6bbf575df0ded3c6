#pragma once
// The configuration space of a translating robot in a World, built once, exactly:
// the obstacles' regularized union (solids), their C-obstacles (Minkowski sums with the
// reflected robot, joined), the bounds as walls, and the open free space's components.
//
// CGAL stays behind this interface (geometry/detail/cspace_impl.hpp holds the arrangement), so
// including this header costs nothing. Exact tests of segments and paths: geometry/path_check.hpp.
#include <polyplan/geometry/world.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

namespace detail {
struct CSpaceAccess;  // the door for polyplan's own CGAL code (geometry/detail/cspace_impl.hpp)
}

// One connected component of the open free space, as the closure's boundary cycles. A cycle may
// visit a pinch vertex twice (the free space touches itself there).
struct FreeComponent {
  Ring outer;                    // empty when the component is unbounded (world without bounds)
  std::vector<Ring> holes;       // C-obstacles (and pieces of wall) inside it
  std::optional<Rational> area;  // exact; none for the unbounded component
};

// Where a configuration (the robot's reference point) lies.
struct Location {
  enum class Kind { free, contact, blocked };
  Kind kind;
  // Free components the point belongs to: one when free; the adjacent ones in contact (two at
  // a pinch point between components); none when blocked.
  std::vector<std::size_t> components;
};

class CSpace {
 public:
  explicit CSpace(const World& world);
  ~CSpace();
  CSpace(CSpace&&) noexcept;
  CSpace& operator=(CSpace&&) noexcept;

  const World& world() const;

  // The obstacles joined into solids (regularized union: touching obstacles are one solid).
  const std::vector<PolygonWithHoles>& solids() const;
  // Connected C-obstacles (the walls of the bounds not included).
  const std::vector<PolygonWithHoles>& cobstacles() const;
  const std::vector<FreeComponent>& free_components() const;
  // The box the reference point must stay in so the whole robot stays in the bounds;
  // none without bounds. Empty (xmin > xmax) when the robot does not fit.
  const std::optional<Bounds>& reference_box() const;

  Location locate(const ExactPoint& p) const;

  // Why the robot cannot be at p, in words that name what it hits ("obstacles[2]", "the
  // bounds"); nullopt when p is free or in contact.
  std::optional<std::string> collision_at(const ExactPoint& p) const;

  // "the start [1, 2] is not free: it is inside obstacles[0]" for the first of the query's start
  // and goal that is not free; nullopt when both are (contact is free). Planners' why_not.
  std::optional<std::string> query_not_free(const Query& query) const;

  // Throws InputError (naming the world file, the query and the obstacle hit) when a start or
  // goal of the world's queries is not free. Poses turned away from 0 degrees ([x, y, theta]) are
  // not configurations of this C-space and are left to the rotation planner.
  void require_free_queries() const;

  struct Impl;  // the CGAL side: incomplete here, defined in geometry/detail/cspace_impl.hpp

 private:
  friend struct detail::CSpaceAccess;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
