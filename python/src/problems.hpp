#pragma once
// What Python's World and Arm hold: the problem a planner is built from, shared by the planners
// and plans made of it (which keep it alive), and a lock. polyplan's planners and C-spaces serve
// one thread, so every call that reads a problem (building its C-space or a planner, planning,
// checking, drawing) holds its lock with the GIL released: calls on two problems run in
// parallel, calls on one problem take turns.
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/registry/problem.hpp>

#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>
#include <string>

namespace polyplan::python {

// What Python's World and Arm share: the problem as the front door takes it (registry/problem.hpp)
// and its lock.
class ProblemHandle {
 public:
  explicit ProblemHandle(Problem problem) : problem_(std::move(problem)) {}
  virtual ~ProblemHandle() = default;
  const Problem& door() const { return problem_; }
  std::mutex& lock() { return mutex_; }

 private:
  Problem problem_;
  std::mutex mutex_;
};

class WorldHandle final : public ProblemHandle {
 public:
  explicit WorldHandle(World world) : ProblemHandle(Problem(std::move(world))) {}
  const World& world() const { return *door().world(); }
  // Built on first use; the caller holds lock().
  const CSpace& cspace() { return door().cspace(); }
};

class ArmHandle final : public ProblemHandle {
 public:
  explicit ArmHandle(ArmProblem problem) : ProblemHandle(Problem(std::move(problem))) {}
  const ArmProblem& problem() const { return *door().arm(); }
};

// `work()` with the GIL released and `lock` held.
template <class Work>
decltype(auto) locked(std::mutex& lock, Work&& work) {
  pybind11::gil_scoped_release released;
  std::lock_guard<std::mutex> held(lock);
  return work();
}

// The World a Python argument is; InputError naming `what` when it is something else.
std::shared_ptr<WorldHandle> world_of(pybind11::handle value, const std::string& what);
// The World or Arm a Python argument is, as the front door takes it; InputError naming `what`.
std::shared_ptr<ProblemHandle> problem_of(pybind11::handle value, const std::string& what);

void bind_problems(pybind11::module_& m);

}  // namespace polyplan::python
