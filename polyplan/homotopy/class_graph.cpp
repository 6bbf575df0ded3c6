#include <polyplan/homotopy/class_graph.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan {

ClassGraph::ClassGraph(const CSpace& cspace) : cspace_(&cspace), signature_(cspace) {
  const VisibilityGraph visibility(cspace);
  const Roadmap& roadmap = visibility.roadmap();
  corners_ = visibility.corner_count();
  positions_.reserve(corners_);
  for (std::size_t v = 0; v < corners_; ++v) positions_.push_back(roadmap[v].exact);
  arcs_.resize(corners_);
  for (const auto e : boost::make_iterator_range(boost::edges(roadmap))) {
    const std::size_t a = boost::source(e, roadmap), b = boost::target(e, roadmap);
    if (a < corners_ && b < corners_) join(a, b);
  }
}

ClassGraph::~ClassGraph() = default;

void ClassGraph::join(std::size_t a, std::size_t b) {
  const ExactPoint &p = positions_[a], &q = positions_[b];
  const LengthBounds length = distance_bounds(p, q);
  Word word = signature_.segment(p, q);
  arcs_[b].push_back({a, length, inverse(word)});
  arcs_[a].push_back({b, length, std::move(word)});
}

std::size_t ClassGraph::add_point(const ExactPoint& p) {
  const std::size_t id = positions_.size();
  positions_.push_back(p);
  arcs_.emplace_back();
  for (std::size_t v = 0; v < id; ++v)
    if (!(positions_[v] == p) && check_segment(*cspace_, p, positions_[v]).valid) join(id, v);
  return id;
}

ClassSearch::ClassSearch(const ClassGraph& graph, std::size_t source, Word word, std::optional<Rational> max_length,
                         std::size_t max_states, Admit admit)
    : graph_(&graph), max_length_(std::move(max_length)), max_states_(max_states), admit_(std::move(admit)) {
  offer(source, std::move(word), ChainLengths::source(graph.position(source)));
}

void ClassSearch::offer(std::size_t vertex, Word word, const ChainLengths::Way& way) {
  if ((max_length_ && chains_.compare(way, *max_length_) > 0) || (admit_ && !admit_(vertex, word))) return;
  auto key = std::make_pair(vertex, word);
  const auto found = ids_.find(key);
  if (found != ids_.end()) {
    const std::size_t id = found->second;
    if (!chains_.closed(id) && chains_.compare(way, chains_.way_to(id)) < 0) chains_.shorten(id, way);
    return;
  }
  if (states_.size() >= max_states_ || letters_ + word.size() > kLettersPerState * max_states_) {
    truncated_ = true;
    return;
  }
  letters_ += word.size();
  ids_.emplace(std::move(key), states_.size());
  states_.push_back({vertex, std::move(word)});
  chains_.add(way);
}

std::optional<std::size_t> ClassSearch::next() {
  const auto id = chains_.close_shortest();
  if (!id) return std::nullopt;
  const State s = states_[*id];  // a copy: offer() may grow states_
  for (const ClassGraph::Arc& arc : graph_->arcs(s.vertex)) {
    Word word = s.word;
    multiply(word, arc.word);
    offer(arc.to, std::move(word), chains_.step(*id, graph_->position(arc.to), arc.length));
  }
  return id;
}

std::vector<std::size_t> ClassSearch::chain_to(std::size_t id) const {
  std::vector<std::size_t> chain;
  for (std::optional<std::size_t> at = id; at; at = chains_.parent(*at)) chain.push_back(*at);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

std::vector<ExactPoint> ClassSearch::path_to(std::size_t id) const {
  std::vector<ExactPoint> path;
  for (const std::size_t s : chain_to(id)) path.push_back(graph_->position(states_[s].vertex));
  return path;
}

std::optional<std::size_t> ClassSearch::find(std::size_t vertex, const Word& word) const {
  const auto found = ids_.find({vertex, word});
  if (found == ids_.end()) return std::nullopt;
  return found->second;
}

}  // namespace polyplan
