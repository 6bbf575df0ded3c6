#pragma once
// Work shared by a few threads, each taking its next piece from a common counter: the pool of
// the experiment runner and of the Euclidean shortest paths' preprocessing and queries.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

#include "polyplan/plan/thread_memory.hpp"

namespace polyplan {

// How many threads a pool asked for, and how many ran.
struct ThreadsRun {
  unsigned asked = 0, started = 0;
  bool short_of_threads() const { return started < asked; }
};

// Runs `work(worker)` on up to `threads` threads at once, the caller's own among them as worker
// 0; fewer under an address-space cap, so that half the headroom stays for the work
// (thread_memory.hpp). A thread the system cannot start (too many threads for its limits, no
// memory for a stack) is not an error either: the pool runs with those that started, so `work` must take its pieces
// from a shared counter (for_each_piece), never a fixed slice per worker. An exception a worker throws (out of memory,
// say) ends that worker and is thrown again to the caller once all have joined — never std::terminate from a thread.
template <class Work>
ThreadsRun run_on_threads(unsigned threads, const Work& work) {
  const unsigned asked = std::max(threads, 1u);
  threads = threads_within_memory(asked);
  std::vector<std::exception_ptr> failures(threads);
  const auto guarded = [&](unsigned worker) {
    try {
      work(worker);
    } catch (...) {
      failures[worker] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (unsigned worker = 1; worker < threads; ++worker) {
    try {
      pool.emplace_back(guarded, worker);
    } catch (const std::system_error&) {  // no thread to be had
      break;
    } catch (const std::bad_alloc&) {  // no memory for the thread's state: the same, not a joinable thread left behind
      break;
    }
  }
  guarded(0u);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  return {asked, static_cast<unsigned>(pool.size() + 1)};
}

// Calls piece(i, worker) for every i in [0, n) once, on up to `threads` threads (no more than n).
template <class Piece>
ThreadsRun for_each_piece(std::size_t n, unsigned threads, const Piece& piece) {
  std::atomic<std::size_t> next{0};
  const auto share = [&](unsigned worker) {
    for (std::size_t i; (i = next.fetch_add(1)) < n;) piece(i, worker);
  };
  return run_on_threads(static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(n, 1))), share);
}

}  // namespace polyplan
