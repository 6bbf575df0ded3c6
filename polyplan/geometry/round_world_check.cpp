// The checks of round_world_check.hpp in rationals: the rules of geometry/detail/round_rules.hpp
// (how a segment and a point are decided) over GMP's field.
#include <polyplan/geometry/round_world_check.hpp>

#include <polyplan/geometry/detail/round_rules.hpp>

namespace polyplan {

namespace {

Rational same(const Rational& x) { return x; }

}  // namespace

struct RoundWorld::Impl {
  World world;
  RoundCSpace cspace;
  round_rules::RoundRules<Rational> rules;

  explicit Impl(const World& w) : world(w), cspace(round_cspace(w)), rules(cspace, same) {}
};

RoundWorld::RoundWorld(const World& world) : impl_(std::make_unique<const Impl>(world)) {}

const World& RoundWorld::world() const { return impl_->world; }
const RoundCSpace& RoundWorld::cspace() const { return impl_->cspace; }
const std::optional<Bounds>& RoundWorld::reference_box() const { return impl_->cspace.box; }
const std::optional<Disc>& RoundWorld::reference_disc() const { return impl_->cspace.disc; }

RoundWorld::~RoundWorld() = default;
RoundWorld::RoundWorld(RoundWorld&&) noexcept = default;
RoundWorld& RoundWorld::operator=(RoundWorld&&) noexcept = default;

std::optional<std::string> RoundWorld::config_not_free(const ExactPoint& q) const {
  const auto c = impl_->rules.contact({q.x, q.y});
  if (c.inside)
    return "(" + to_string(q.x) + ", " + to_string(q.y) +
           ") is not free: " + (c.inside_of == "the bounds" ? "outside the bounds" : "it overlaps " + c.inside_of);
  return std::nullopt;
}

PathCheck RoundWorld::check_segment(const ExactPoint& a, const ExactPoint& b) const { return check_path({a, b}); }

PathCheck RoundWorld::check_path(const std::vector<ExactPoint>& given) const {
  using Point = round_rules::P<Rational>;
  std::vector<Point> path;
  for (const ExactPoint& p : given)
    if (path.empty() || !(path.back() == Point{p.x, p.y})) path.push_back({p.x, p.y});
  if (path.empty()) return {false, "the path is empty", std::nullopt};
  const auto invalid = [](std::size_t segment, const std::string& why) { return PathCheck{false, why, segment}; };
  int face = 0;  // the side of a wall the path slides along (round_rules' blocked_at)
  for (std::size_t i = 0; i < path.size(); ++i) {
    std::optional<Point> in, out;
    if (i > 0) in = path[i - 1] - path[i];
    if (i + 1 < path.size()) out = path[i + 1] - path[i];
    face = -face;
    if (auto why = impl_->rules.blocked_at(path[i], in, out, face)) return invalid(i == 0 ? 0 : i - 1, *why);
  }
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (auto why = impl_->rules.segment_blocked(path[i], path[i + 1])) return invalid(i, *why);
  return {};
}

}  // namespace polyplan
