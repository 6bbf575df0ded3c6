#include <polyplan/geometry/chain_lengths.hpp>

namespace polyplan {

std::size_t ChainLengths::add(const Way& way) {
  states_.push_back(way);
  closed_.push_back(false);
  open_.insert(states_.size() - 1);
  return states_.size() - 1;
}

void ChainLengths::shorten(std::size_t id, const Way& way) {
  open_.erase(id);  // before its length changes, which orders it
  states_[id] = way;
  open_.insert(id);
}

std::optional<std::size_t> ChainLengths::close_shortest() {
  if (open_.empty()) return std::nullopt;
  const std::size_t id = *open_.begin();
  open_.erase(open_.begin());
  closed_[id] = true;
  return id;
}

RootSum ChainLengths::exact(const Way& way) const {
  RootSum sum;
  const ExactPoint* at = way.at;
  for (std::optional<std::size_t> p = way.parent; p; p = states_[*p].parent) {
    sum.add(squared_distance(*states_[*p].at, *at));
    at = states_[*p].at;
  }
  return sum;
}

int ChainLengths::compare(const Way& a, const Way& b) const {
  if (const int sign = compare_bounds(a.bounds, b.bounds)) return sign;
  return polyplan::compare(exact(a), exact(b));
}

int ChainLengths::compare(const Way& a, const Rational& c) const {
  if (const int sign = compare_bounds(a.bounds, rational_bounds(c))) return sign;
  return polyplan::compare(exact(a), c);
}

bool ChainLengths::Shorter::operator()(std::size_t a, std::size_t b) const {
  const int sign = chains->compare(chains->states_[a], chains->states_[b]);
  return sign != 0 ? sign < 0 : a < b;
}

}  // namespace polyplan
