#pragma once
// The front door's problem (docs/architecture.md "The front door"): anything polyplan plans for,
// read from its file by one call — a polygon world (a translating, turning or steered robot among
// polygons; docs/design.md "World file") or a planar arm among obstacles ("Arm file").
// make_planner (registry/any_planner.hpp) builds a registry planner for it; nothing above this
// folder asks which kind of problem it holds.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace polyplan {

struct World;
struct ArmProblem;
class CSpace;
class RoundWorld;

class Problem {
 public:
  // A world or an arm file, whichever it is (an arm file has "links"). InputError naming the file
  // and the field for anything wrong; unknown fields go to `warnings` (printed when it is null).
  static Problem read(const std::string& path, std::vector<std::string>* warnings = nullptr);
  // The same from the file's text in memory; `name` stands for the file in messages.
  static Problem parse(const std::string& text, const std::string& name, std::vector<std::string>* warnings = nullptr);
  explicit Problem(World world);
  explicit Problem(ArmProblem arm);

  // The file it was read from, for messages.
  const std::string& source() const;
  // The names of its queries, in order ("start/goal", "queries[1]", an arm query's name).
  std::vector<std::string> query_names() const;

  // The problem itself, for the code that reads one kind (checks, pictures of a world alone):
  // null when the problem is of the other kind.
  const World* world() const;
  const ArmProblem* arm() const;
  // A world's C-space for a translating robot, built on first use and kept (a problem serves one
  // thread at a time, as its planners do); std::logic_error for an arm.
  const CSpace& cspace() const;
  // A world's exact checks among its discs and walls, for a point or disc robot
  // (geometry/round_world_check.hpp), built on first use and kept alike; InputError for a polygon
  // robot, std::logic_error for an arm.
  const RoundWorld& round_world() const;
  // Builds now what the planners of a world share (its C-space), rather than on first use: a
  // timed planner construction then measures the planner alone.
  void prepare() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace polyplan
