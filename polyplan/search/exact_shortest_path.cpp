#include <polyplan/search/exact_shortest_path.hpp>

#include <polyplan/geometry/chain_lengths.hpp>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace polyplan {
namespace {

LengthBounds edge_bounds(const Roadmap& roadmap, RoadmapVertexId a, RoadmapVertexId b) {
  return distance_bounds(roadmap[a].x, roadmap[a].y, roadmap[b].x, roadmap[b].y);
}

// The vertices from the start to `id`'s vertex.
std::vector<RoadmapVertexId> path_to(const ChainLengths& chains, const std::vector<RoadmapVertexId>& vertex_of,
                                     std::size_t id) {
  std::vector<RoadmapVertexId> path;
  for (std::optional<std::size_t> at = id; at; at = chains.parent(*at)) path.push_back(vertex_of[*at]);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::vector<RoadmapVertexId> exactly_shortest_path(const Roadmap& roadmap, const std::vector<RoadmapVertexId>& found) {
  if (found.size() <= 2) return found;  // one segment: the straight line, nothing is shorter
  const RoadmapVertexId start = found.front(), goal = found.back();
  std::vector<ExactPoint> corners;
  for (const RoadmapVertexId v : found) corners.push_back(roadmap[v].exact);
  const RootSum searched = RootSum::polyline(corners);
  // Dijkstra, exactly, over the vertices of paths that may be no longer than the search's.
  ChainLengths chains;
  std::vector<RoadmapVertexId> vertex_of{start};
  std::unordered_map<RoadmapVertexId, std::size_t> id_of{
      {start, chains.add(ChainLengths::source(roadmap[start].exact))}};
  while (const auto id = chains.close_shortest()) {
    const RoadmapVertexId v = vertex_of[*id];
    if (v == goal) {
      if (compare(searched, chains.exact(chains.way_to(*id))) <= 0) return found;
      return path_to(chains, vertex_of, *id);
    }
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, roadmap))) {
      const RoadmapVertexId w = boost::target(e, roadmap);
      const auto way = chains.step(*id, roadmap[w].exact, edge_bounds(roadmap, v, w));
      if ((way.bounds + edge_bounds(roadmap, w, goal)).lower > searched.bounds().upper) continue;
      const auto known = id_of.find(w);
      if (known == id_of.end()) {
        id_of.emplace(w, chains.add(way)), vertex_of.push_back(w);
      } else if (!chains.closed(known->second) && chains.compare(way, chains.way_to(known->second)) < 0) {
        chains.shorten(known->second, way);
      }
    }
  }
  throw std::logic_error("exactly_shortest_path: the search's path is not a path of the roadmap");
}

}  // namespace polyplan
