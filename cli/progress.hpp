#pragma once
// Progress of a long run on stderr, about once a second, so that a person knows it is working
// while standard output stays the answer (JSON or a table).
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace polyplan::cli {

class Progress {
 public:
  using Clock = std::chrono::steady_clock;

  explicit Progress(std::string what) : what_(std::move(what)) {}

  // "\rWHAT: done/total", at most once a second and always at the end (then a newline).
  void update(std::size_t done, std::size_t total) {
    if (std::chrono::duration<double>(Clock::now() - last_).count() < 1.0 && done != total) return;
    last_ = Clock::now();
    std::fprintf(stderr, "\r%s: %zu/%zu", what_.c_str(), done, total);
    if (done == total) std::fprintf(stderr, "\n");
  }

 private:
  std::string what_;
  Clock::time_point last_ = Clock::now();
};

}  // namespace polyplan::cli
