#pragma once
// The roadmap that prm and lazyprm grow and keep from query to query: milestones (configurations
// with a nearest-neighbour index) and a Boost graph whose edges join each new milestone to its k
// nearest, k fixed or k = ⌈e·(1 + 1/d)·log n⌉ (PRM*'s), searched with search/graph_search.hpp.
// prm certifies an edge before adding it; lazyprm adds it unchecked and certifies it when a search
// wants it (`certified`). A query's goals are milestones each; its path goes to the one the
// roadmap reaches most cheaply; with a roadmap built before the queries (roadmap-size), its start
// and goals only visit it. Private to the two planners' sources (it includes the BGL algorithms).
#include <polyplan/sampling/sampling_planner.hpp>
#include <polyplan/search/bidirectional_search.hpp>
#include <polyplan/search/graph_search.hpp>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace polyplan::detail {

// What a roadmap does with a new milestone's neighbour.
enum class Join {
  none,         // no edge: the motion is blocked
  certified,    // an edge whose motion is proved free already (PRM)
  uncertified,  // an edge to be certified when a path uses it (lazy PRM)
};

struct SampledEdge {
  double length = 0;
  bool certified = false;
};

template <class Space>
class SampledRoadmap {
 public:
  using Configuration = typename Space::Configuration;
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, SampledEdge>;
  using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;

  SampledRoadmap(const SamplingSpace<Space>& space, std::size_t k) : space_(&space), nodes_(space), k_(k) {
    k_factor_ = std::numbers::e * (1 + 1 / static_cast<double>(space.dimension()));
  }

  // Adds a milestone at its coordinates `at` (none: the space gives them, for a query's start or
  // goal); `join(neighbour)` says, for each of its nearest milestones, nearest first, which Join
  // to make.
  template <class JoinNeighbour>
  std::size_t add(Configuration configuration, std::span<const double> at, JoinNeighbour join) {
    if (at.empty()) {
      scratch_.resize(space_->dimension());
      space_->coordinates(configuration, scratch_);
      at = scratch_;
    }
    nodes_.nearest(at, neighbour_count(), near_);
    const std::size_t id = nodes_.add(std::move(configuration), at);
    boost::add_vertex(graph_);
    for (std::size_t n : near_)
      if (const Join how = join(n); how != Join::none)
        boost::add_edge(n, id, SampledEdge{edge_length(n, at), how == Join::certified}, graph_);
    return id;
  }

  // A configuration joined to the roadmap for one query (its start or a goal) without becoming a
  // milestone: a vertex after the milestones, kept out of the nearest-neighbour index and removed
  // by leave(), so that every query finds the roadmap as it was built. `join(neighbour)` as
  // add()'s, for each of its nearest milestones. No milestone may be added while one visits.
  template <class JoinNeighbour>
  std::size_t visit(Configuration configuration, JoinNeighbour join) {
    std::vector<double> at(space_->dimension());
    space_->coordinates(configuration, at);
    nodes_.nearest(at, neighbour_count(), near_);
    const std::size_t id = boost::add_vertex(graph_);
    for (std::size_t n : near_)
      if (const Join how = join(n); how != Join::none)
        boost::add_edge(n, id, SampledEdge{edge_length(n, at), how == Join::certified}, graph_);
    visitors_.push_back({std::move(configuration), std::move(at)});
    return id;
  }
  // Removes the visitors and their edges (the last vertices: the milestones keep their ids).
  void leave() {
    for (; !visitors_.empty(); visitors_.pop_back()) {
      const Vertex last = boost::num_vertices(graph_) - 1;
      boost::clear_vertex(last, graph_);
      boost::remove_vertex(last, graph_);
    }
  }
  // Vertex v's configuration: a milestone's or a visitor's.
  const Configuration& configuration(std::size_t v) const {
    return v < nodes_.size() ? nodes_[v] : visitors_[v - nodes_.size()].configuration;
  }
  // Each vertex's connected component, numbered 0, 1, ... in order of their first vertex, into
  // `out`; returns how many there are.
  std::size_t components(std::vector<std::size_t>& out) const {
    out.assign(boost::num_vertices(graph_), 0);
    return boost::connected_components(graph_, out.data());
  }

  // The shortest path start → goal over the edges there are (certified or not), by `options`
  // with the distance to the goal as heuristic.
  SearchResult<Vertex> search(std::size_t start, std::size_t goal, const SearchOptions& options) {
    const auto to_goal = coordinates(goal);
    return shortest_path(
        graph_, start, goal, options, [&](Vertex v) { return space_->distance(coordinates(v), to_goal); },
        [&](const typename Graph::edge_descriptor& e) { return graph_[e].length; }, workspace_);
  }

  SearchResult<Vertex> search_both_ways(std::size_t start, std::size_t goal) {
    return bidirectional_dijkstra(graph_, start, goal,
                                  [&](const typename Graph::edge_descriptor& e) { return graph_[e].length; });
  }

  // The cheapest of the paths that `search_one(start, goal)` (search or search_both_ways) finds to
  // each of `goals`, the first of equals; its counts are all the searches'. Not found when none is.
  template <class SearchOne>
  static SearchResult<Vertex> cheapest(std::size_t start, const std::vector<std::size_t>& goals, SearchOne search_one) {
    SearchResult<Vertex> best;
    std::size_t expanded = 0, generated = 0;
    for (std::size_t goal : goals) {
      SearchResult<Vertex> result = search_one(start, goal);
      expanded += result.expanded, generated += result.generated;
      if (result.found && (!best.found || result.cost < best.cost)) best = std::move(result);
    }
    best.expanded = expanded, best.generated = generated;
    return best;
  }

  const SampledConfigurations<Space>& nodes() const { return nodes_; }
  Graph& graph() { return graph_; }
  std::size_t size() const { return nodes_.size(); }
  std::size_t edges() const { return boost::num_edges(graph_); }

  std::shared_ptr<const PlanGraph<Configuration>> picture() const {
    auto picture = std::make_shared<PlanGraph<Configuration>>();
    picture->kind = "roadmap";
    picture->vertices = nodes_.all();
    for (const Visitor& visitor : visitors_) picture->vertices.push_back(visitor.configuration);
    for (auto [e, end] = boost::edges(graph_); e != end; ++e)
      picture->edges.emplace_back(boost::source(*e, graph_), boost::target(*e, graph_));
    return picture;
  }

 private:
  // An edge's length: its motion's, or in a space that is not symmetric the longer of its two
  // (so that the distance to the goal stays a lower bound on the search's costs, which the
  // triangle inequality of a shortest curves' length gives).
  double edge_length(std::size_t n, std::span<const double> at) const {
    const double there = space_->distance(nodes_.coordinates(n), at);
    return space_->symmetric() ? there : std::max(there, space_->distance(at, nodes_.coordinates(n)));
  }
  std::span<const double> coordinates(std::size_t v) const {
    return v < nodes_.size() ? nodes_.coordinates(v) : std::span<const double>(visitors_[v - nodes_.size()].at);
  }
  std::size_t neighbour_count() const {
    if (k_ > 0) return k_;
    return static_cast<std::size_t>(std::ceil(k_factor_ * std::log(static_cast<double>(nodes_.size()) + 1)));
  }

  const SamplingSpace<Space>* space_;
  SampledConfigurations<Space> nodes_;
  std::size_t k_;
  double k_factor_ = 0;
  Graph graph_;
  SearchWorkspace<Vertex> workspace_;
  std::vector<std::size_t> near_;
  std::vector<double> scratch_;
  struct Visitor {
    Configuration configuration;
    std::vector<double> at;
  };
  std::vector<Visitor> visitors_;
};

}  // namespace polyplan::detail
