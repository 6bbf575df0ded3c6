#include <polyplan/registry/problem.hpp>

#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/io/detail/text_file.hpp>
#include <polyplan/io/world_reader.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <variant>

namespace polyplan {

struct Problem::State {
  std::variant<World, ArmProblem> problem;
  std::unique_ptr<CSpace> cspace;           // a world's, built on first use
  std::unique_ptr<RoundWorld> round_world;  // likewise, for a world with discs or walls
};

Problem::Problem(World world) : state_(std::make_shared<State>(State{std::move(world), nullptr, nullptr})) {}
Problem::Problem(ArmProblem arm) : state_(std::make_shared<State>(State{std::move(arm), nullptr, nullptr})) {}

Problem Problem::read(const std::string& path, std::vector<std::string>* warnings) {
  return parse(detail::read_text_file(path), path, warnings);
}

Problem Problem::parse(const std::string& text, const std::string& name, std::vector<std::string>* warnings) {
  // An arm file is the one with links; anything else, malformed text included, is read as a
  // world, whose reader says what is wrong.
  const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
  if (root.is_object() && root.contains("links")) return Problem(parse_arm_problem(text, name, warnings));
  return Problem(parse_world(text, name, warnings));
}

const std::string& Problem::source() const {
  return std::visit([](const auto& p) -> const std::string& { return p.source; }, state_->problem);
}

std::vector<std::string> Problem::query_names() const {
  std::vector<std::string> names;
  std::visit(
      [&](const auto& p) {
        for (const auto& q : p.queries) names.push_back(q.name);
      },
      state_->problem);
  return names;
}

const World* Problem::world() const { return std::get_if<World>(&state_->problem); }
const ArmProblem* Problem::arm() const { return std::get_if<ArmProblem>(&state_->problem); }

const CSpace& Problem::cspace() const {
  const World* w = world();
  if (!w)
    throw std::logic_error("Problem::cspace: " + source() + " is an arm, which has no C-space of a translating robot");
  if (!state_->cspace) state_->cspace = std::make_unique<CSpace>(*w);
  return *state_->cspace;
}

const RoundWorld& Problem::round_world() const {
  const World* w = world();
  if (!w) throw std::logic_error("Problem::round_world: " + source() + " is an arm");
  if (!state_->round_world) state_->round_world = std::make_unique<RoundWorld>(*w);
  return *state_->round_world;
}

void Problem::prepare() const {
  if (!world() || world()->robot.car) return;  // a car's planners build their own
  if (round_features(*world()).empty()) cspace();
  else round_world();
}

}  // namespace polyplan
