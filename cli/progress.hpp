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

  // "\rWHAT: done/total, 12 s elapsed, about 30 s left", at most once a second and always at the
  // end (then a newline). The estimate assumes the rest goes at the pace so far.
  void update(std::size_t done, std::size_t total) {
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_).count() < 1.0 && done != total) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - started_).count();
    std::fprintf(stderr, "\r%s: %zu/%zu, %.0f s elapsed", what_.c_str(), done, total, elapsed);
    if (done > 0 && done < total)
      std::fprintf(stderr, ", about %.0f s left   ",
                   elapsed / static_cast<double>(done) * static_cast<double>(total - done));
    else std::fprintf(stderr, "%20s", "");
    if (done == total) std::fprintf(stderr, "\n");
  }

 private:
  std::string what_;
  Clock::time_point started_ = Clock::now();
  Clock::time_point last_ = Clock::now();
};

}  // namespace polyplan::cli
