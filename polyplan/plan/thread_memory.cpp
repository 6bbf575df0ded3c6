#include "polyplan/plan/thread_memory.hpp"

#include <pthread.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace polyplan {
namespace {

// The address space the process takes now: /proc/self/statm's first field, in pages.
std::uint64_t address_space_taken() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// The stack a std::thread gets: the process's default thread attributes.
std::uint64_t thread_stack_size() {
  pthread_attr_t attributes;
  std::size_t size = 0;
  if (pthread_getattr_default_np(&attributes) != 0) return 8u << 20;
  pthread_attr_getstacksize(&attributes, &size);
  pthread_attr_destroy(&attributes);
  return std::max<std::uint64_t>(size, 1);
}

}  // namespace

unsigned threads_within_memory(unsigned asked) {
  rlimit cap{};
  if (getrlimit(RLIMIT_AS, &cap) != 0 || cap.rlim_cur == RLIM_INFINITY) return asked;
  const std::uint64_t taken = address_space_taken();
  const std::uint64_t headroom = cap.rlim_cur > taken ? cap.rlim_cur - taken : 0;
  const std::uint64_t fit = headroom / (2 * thread_stack_size());
  return static_cast<unsigned>(std::clamp<std::uint64_t>(fit, 1, std::max(asked, 1u)));
}

}  // namespace polyplan
