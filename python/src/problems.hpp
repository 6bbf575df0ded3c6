#pragma once
// What Python's World and Arm hold: the problem a planner is built from, shared by the planners
// and plans made of it (which keep it alive), and a lock. polyplan's planners and C-spaces serve
// one thread, so every call that reads a problem (building its C-space or a planner, planning,
// checking, drawing) holds its lock with the GIL released: calls on two problems run in
// parallel, calls on one problem take turns.
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/world.hpp>

#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>
#include <string>

namespace polyplan::python {

class WorldHandle {
 public:
  explicit WorldHandle(World world) : world_(std::move(world)) {}
  const World& world() const { return world_; }
  // Built on first use; the caller holds lock().
  const CSpace& cspace() {
    if (!cspace_) cspace_ = std::make_unique<CSpace>(world_);
    return *cspace_;
  }
  std::mutex& lock() { return mutex_; }

 private:
  World world_;
  std::unique_ptr<CSpace> cspace_;
  std::mutex mutex_;
};

class ArmHandle {
 public:
  explicit ArmHandle(ArmProblem problem) : problem_(std::move(problem)) {}
  const ArmProblem& problem() const { return problem_; }
  std::mutex& lock() { return mutex_; }

 private:
  ArmProblem problem_;
  std::mutex mutex_;
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

void bind_problems(pybind11::module_& m);

}  // namespace polyplan::python
