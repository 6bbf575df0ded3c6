#include <polyplan/geometry/shared_component.hpp>

#include <algorithm>

namespace polyplan {

bool share_a_component(const CSpace& cspace, const ExactPoint& a, const ExactPoint& b) {
  const std::vector<std::size_t> at_a = cspace.locate(a).components, at_b = cspace.locate(b).components;
  return std::any_of(at_a.begin(), at_a.end(),
                     [&](std::size_t c) { return std::find(at_b.begin(), at_b.end(), c) != at_b.end(); });
}

}  // namespace polyplan
