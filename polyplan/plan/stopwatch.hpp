#pragma once
// Seconds since construction on the steady clock: how planners time building and querying.
#include <chrono>
#include <memory>
#include <utility>

namespace polyplan {

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(); }

 private:
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

// A planner's built part (its Impl), made from `args` and told how long that took (its
// build_seconds: the roadmap.seconds fact).
template <class Built, class... Args>
std::unique_ptr<Built> build_timed(Args&&... args) {
  const Stopwatch building;
  auto built = std::make_unique<Built>(std::forward<Args>(args)...);
  built->build_seconds = building.seconds();
  return built;
}

}  // namespace polyplan
