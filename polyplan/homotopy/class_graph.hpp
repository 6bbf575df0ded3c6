#pragma once
// The graph the homotopy searches run over: the C-space's reduced visibility graph (whose paths
// hold the shortest path of every homotopy class: a taut path bends only round corners, along
// tangents) plus the points a query adds, each directed arc with bounds on its length and its
// word (homotopy/h_signature.hpp); and a Dijkstra over (vertex, reduced word) — the graph's lift
// to the classes, where the first time a (vertex, word) is settled is the shortest path to the
// vertex in that class. Its lengths are sums of square roots, compared exactly
// (geometry/root_sum.hpp): the order of the classes and a bound such as the tether's length are
// decided as exactly as the geometry, ties included.
#include <polyplan/geometry/chain_lengths.hpp>
#include <polyplan/homotopy/h_signature.hpp>

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace polyplan {

class ClassGraph {
 public:
  struct Arc {
    std::size_t to;
    LengthBounds length;
    Word word;
  };

  // `cspace` must outlive the graph.
  explicit ClassGraph(const CSpace& cspace);
  ~ClassGraph();

  // Adds p as a vertex joined to every corner and every added point it sees (exact segment
  // checks); returns its id.
  std::size_t add_point(const ExactPoint& p);

  const CSpace& cspace() const { return *cspace_; }
  const HSignature& signature() const { return signature_; }
  std::size_t size() const { return positions_.size(); }
  const ExactPoint& position(std::size_t v) const { return positions_[v]; }
  const std::vector<Arc>& arcs(std::size_t v) const { return arcs_[v]; }

 private:
  void join(std::size_t a, std::size_t b);
  const CSpace* cspace_;
  HSignature signature_;
  std::size_t corners_ = 0;
  std::vector<ExactPoint> positions_;
  std::vector<std::vector<Arc>> arcs_;
};

// Dijkstra over (vertex, reduced word) from one vertex and starting word, settling states in order
// of distance: next() gives the next settled state. `admit(vertex, word)` may refuse a state (the
// tether's bound); states longer than `max_length` (none: no bound) or past `max_states` are not made, nor
// states whose words would hold more than kLettersPerState × max_states letters in all: a word
// grows with every winding, so a bound on states alone bounds no memory (10,000 classes round a
// pillar took gigabytes).
inline constexpr std::size_t kLettersPerState = 32;
class ClassSearch {
 public:
  struct State {
    std::size_t vertex;
    Word word;
  };
  using Admit = std::function<bool(std::size_t vertex, const Word& word)>;

  ClassSearch(const ClassGraph& graph, std::size_t source, Word word, std::optional<Rational> max_length,
              std::size_t max_states, Admit admit = {});

  // The next state settled (its id), or nullopt when none is left.
  std::optional<std::size_t> next();
  const State& state(std::size_t id) const { return states_[id]; }
  // The length of the chain from the source to the state, exactly.
  RootSum exact_distance(std::size_t id) const { return chains_.exact(chains_.way_to(id)); }
  // The states from the source to the state, and their vertices' positions.
  std::vector<std::size_t> chain_to(std::size_t id) const;
  std::vector<ExactPoint> path_to(std::size_t id) const;
  // The state (vertex, word), if it was made.
  std::optional<std::size_t> find(std::size_t vertex, const Word& word) const;
  std::size_t states() const { return states_.size(); }
  // Whether max_states (or its letters) stopped states from being made.
  bool truncated() const { return truncated_; }

 private:
  void offer(std::size_t vertex, Word word, const ChainLengths::Way& way);
  const ClassGraph* graph_;
  std::optional<Rational> max_length_;
  std::size_t max_states_;
  std::size_t letters_ = 0;  // in the words of states_
  Admit admit_;
  bool truncated_ = false;
  std::vector<State> states_;
  ChainLengths chains_;  // the states' lengths, the same ids
  std::map<std::pair<std::size_t, Word>, std::size_t> ids_;
};

}  // namespace polyplan
