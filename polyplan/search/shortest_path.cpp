#include <polyplan/search/shortest_path.hpp>

#include <polyplan/search/graph_search.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

struct EuclideanToGoal {
  const Roadmap* roadmap;
  double goal_x, goal_y;
  double operator()(RoadmapVertexId v) const {
    const RoadmapVertex& p = (*roadmap)[v];
    return std::hypot(p.x - goal_x, p.y - goal_y);
  }
};

struct EdgeLength {
  const Roadmap* roadmap;
  double operator()(const boost::graph_traits<Roadmap>::edge_descriptor& e) const { return (*roadmap)[e].length; }
};

}  // namespace

SearchResult<RoadmapVertexId> shortest_path(const Roadmap& roadmap, RoadmapVertexId start, RoadmapVertexId goal,
                                            const SearchOptions& options, SearchWorkspace<RoadmapVertexId>& workspace) {
  if (start >= num_vertices(roadmap) || goal >= num_vertices(roadmap))
    throw std::out_of_range("shortest_path: start or goal is not a vertex of the roadmap");
  return shortest_path(roadmap, start, goal, options, EuclideanToGoal{&roadmap, roadmap[goal].x, roadmap[goal].y},
                       EdgeLength{&roadmap}, workspace);
}

SearchResult<RoadmapVertexId> shortest_path(const Roadmap& roadmap, RoadmapVertexId start, RoadmapVertexId goal,
                                            const SearchOptions& options) {
  SearchWorkspace<RoadmapVertexId> workspace(VertexStorage::hashed);
  return shortest_path(roadmap, start, goal, options, workspace);
}

}  // namespace polyplan
