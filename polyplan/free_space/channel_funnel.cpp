#include <polyplan/free_space/channel_funnel.hpp>

#include <polyplan/geometry/polyline.hpp>

namespace polyplan {

// The funnel is the apex (the last bend) and two rays through the tightest left and right portal
// ends seen so far. A new portal end that narrows the funnel moves its ray; one that crosses the
// other ray makes that ray's end a bend — the new apex, from whose portal the walk restarts.
std::vector<ExactPoint> funnel_path(const ExactPoint& start, const std::vector<Portal>& portals,
                                    const ExactPoint& goal) {
  std::vector<Portal> gates;
  gates.reserve(portals.size() + 2);
  gates.push_back({start, start});
  gates.insert(gates.end(), portals.begin(), portals.end());
  gates.push_back({goal, goal});

  std::vector<ExactPoint> path{start};
  ExactPoint apex = start, left = start, right = start;
  std::size_t left_gate = 0, right_gate = 0;
  for (std::size_t i = 1; i < gates.size(); ++i) {
    const Portal& gate = gates[i];
    if (orientation(apex, right, gate.right) >= 0) {  // not right of the right ray: narrows
      if (apex == right || orientation(apex, left, gate.right) < 0) {
        right = gate.right;
        right_gate = i;
      } else {  // crosses the left ray: the path bends at the left end
        apex = left;
        path.push_back(apex);
        right = apex;
        right_gate = left_gate;
        i = left_gate;
        continue;
      }
    }
    if (orientation(apex, left, gate.left) <= 0) {  // not left of the left ray: narrows
      if (apex == left || orientation(apex, right, gate.left) > 0) {
        left = gate.left;
        left_gate = i;
      } else {  // crosses the right ray: the path bends at the right end
        apex = right;
        path.push_back(apex);
        left = apex;
        left_gate = right_gate;
        i = right_gate;
        continue;
      }
    }
  }
  path.push_back(goal);
  return without_straight_corners(path);
}

}  // namespace polyplan
