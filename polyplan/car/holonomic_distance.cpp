#include <polyplan/car/holonomic_distance.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {

struct HolonomicDistance::Impl {
  World point_world;
  CSpace cspace;
  VisibilityGraph graph;
  std::vector<double> x, y, distance;  // per corner
  double goal_x = 0, goal_y = 0;

  explicit Impl(World world) : point_world(std::move(world)), cspace(point_world), graph(cspace) {}
};

namespace {

World as_point_world(const World& world) {
  World point = world;
  point.robot = Robot{};
  point.queries.clear();
  return point;
}

}  // namespace

HolonomicDistance::HolonomicDistance(const World& world) : impl_(std::make_unique<Impl>(as_point_world(world))) {
  const Roadmap& roadmap = impl_->graph.roadmap();
  for (std::size_t v = 0; v < impl_->graph.corner_count(); ++v) {
    impl_->x.push_back(roadmap[v].x);
    impl_->y.push_back(roadmap[v].y);
  }
}

HolonomicDistance::~HolonomicDistance() = default;
HolonomicDistance::HolonomicDistance(HolonomicDistance&&) noexcept = default;
HolonomicDistance& HolonomicDistance::operator=(HolonomicDistance&&) noexcept = default;

std::size_t HolonomicDistance::corners() const { return impl_->x.size(); }

void HolonomicDistance::set_goal(const ExactPoint& goal) {
  Impl& s = *impl_;
  s.goal_x = to_double(goal.x);
  s.goal_y = to_double(goal.y);
  // The corner graph with the goal joined to the corners it sees, searched from the goal.
  const std::size_t n = s.x.size();
  Roadmap roadmap;
  const Roadmap& corners = s.graph.roadmap();
  for (std::size_t v = 0; v < n; ++v) add_vertex(roadmap, corners[v].exact);
  for (const auto e : boost::make_iterator_range(boost::edges(corners))) {
    const auto u = boost::source(e, corners), v = boost::target(e, corners);
    if (u < n && v < n) boost::add_edge(u, v, corners[e], roadmap);
  }
  const RoadmapVertexId target = add_vertex(roadmap, goal);
  if (!s.cspace.collision_at(goal))
    for (std::size_t v = 0; v < n; ++v)
      if (check_segment(s.cspace, corners[v].exact, goal).valid) add_edge(roadmap, v, target);
  std::vector<double> distance(n + 1);
  boost::dijkstra_shortest_paths(
      roadmap, target, boost::weight_map(boost::get(&RoadmapEdge::length, roadmap)).distance_map(distance.data()));
  distance.pop_back();
  s.distance = std::move(distance);
}

bool HolonomicDistance::separated(const ExactPoint& a, const ExactPoint& b) const {
  const Location at_a = impl_->cspace.locate(a), at_b = impl_->cspace.locate(b);
  for (const std::size_t c : at_a.components)
    if (std::find(at_b.components.begin(), at_b.components.end(), c) != at_b.components.end()) return false;
  return !at_a.components.empty() && !at_b.components.empty();
}

double HolonomicDistance::lower_bound(double x, double y) const {
  const Impl& s = *impl_;
  double best = std::hypot(x - s.goal_x, y - s.goal_y);
  for (std::size_t v = 0; v < s.x.size(); ++v)
    best = std::min(best, std::hypot(x - s.x[v], y - s.y[v]) + s.distance[v]);
  return best;
}

}  // namespace polyplan
