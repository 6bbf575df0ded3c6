#pragma once
// Seconds since construction on the steady clock: how planners time building and querying.
#include <chrono>

namespace polyplan {

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(); }

 private:
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace polyplan
