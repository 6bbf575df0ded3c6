#pragma once
// CSpace's CGAL side: the free space as a Polygon_set_2 whose arrangement answers point
// location and path checks, for polyplan's own code that works on the arrangement (path checks,
// the free-space triangulation of the roadmaps). Not installed; include only from .cpp files.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/detail/cgal_types.hpp>

#include <CGAL/Arr_trapezoid_ric_point_location.h>
#include <CGAL/Polygon_set_2.h>

#include <unordered_map>

namespace polyplan {

struct CSpace::Impl {
  using PolygonSet = CGAL::Polygon_set_2<detail::Kernel>;
  using Arrangement = PolygonSet::Arrangement_2;
  // Randomized incremental trapezoidal map: exact and terminating on every arrangement. CGAL's
  // landmark location (used before) walks from a nearest landmark found with double
  // approximations and looped for ever next to a vertex where two obstacles touch (CGAL issue
  // #6594) and on coordinates near 1e160 or 1e-200.
  using PointLocation = CGAL::Arr_trapezoid_ric_point_location<Arrangement>;
  using Face = Arrangement::Face_const_handle;
  using Vertex = Arrangement::Vertex_const_handle;
  using Halfedge = Arrangement::Halfedge_const_handle;

  World world;
  std::vector<PolygonWithHoles> solids;
  std::vector<PolygonWithHoles> cobstacles;
  std::vector<FreeComponent> free_components;
  std::optional<Bounds> reference_box;

  // The open free space: its arrangement's "contained" faces are the free components.
  PolygonSet free_set;
  std::unordered_map<const void*, std::size_t> component_of_face;  // keyed by &*face
  std::unique_ptr<PointLocation> point_location;

  // The free component of a face, if the face is free.
  std::optional<std::size_t> component(Face face) const {
    auto it = component_of_face.find(&*face);
    if (it == component_of_face.end()) return std::nullopt;
    return it->second;
  }
};

namespace detail {

// The arrangement behind a CSpace, for the code above that needs more than the public interface.
struct CSpaceAccess {
  static const CSpace::Impl& impl(const CSpace& cspace) { return *cspace.impl_; }
};

}  // namespace detail
}  // namespace polyplan
