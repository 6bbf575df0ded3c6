#pragma once
// Counts the bytes a benchmark program holds on the heap: every operator new and every GMP
// allocation (exact numbers live there), so that "memory" means the peak of what a build
// allocated, not the process's resident size, which the allocator's caching blurs. It replaces the
// global operator new and delete: include it in the one source file of a benchmark program.
#include <gmp.h>
#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <new>

namespace polyplan::bench {

inline std::atomic<long long> heap_bytes{0}, heap_peak{0};

inline void note_heap(long long change) {
  const long long now = heap_bytes += change;
  for (long long peak = heap_peak; now > peak && !heap_peak.compare_exchange_weak(peak, now);) {
  }
}

inline void* counted_allocation(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (!p) throw std::bad_alloc();
  note_heap(static_cast<long long>(malloc_usable_size(p)));
  return p;
}

inline void counted_release(void* p) {
  if (!p) return;
  note_heap(-static_cast<long long>(malloc_usable_size(p)));
  std::free(p);
}

inline void* gmp_reallocation(void* p, std::size_t, std::size_t size) {
  const long long before = p ? static_cast<long long>(malloc_usable_size(p)) : 0;
  void* q = std::realloc(p, size);
  if (!q) std::abort();  // GMP cannot recover from a failed allocation either
  note_heap(static_cast<long long>(malloc_usable_size(q)) - before);
  return q;
}

// GMP's allocations counted too; call first thing in main, before any exact number exists.
inline void count_gmp_allocations() {
  mp_set_memory_functions([](std::size_t size) { return counted_allocation(size); }, gmp_reallocation,
                          [](void* p, std::size_t) { counted_release(p); });
}

// The peak of the bytes held while `work` runs, above what was held before it began.
template <class Work>
long long peak_heap_bytes(Work&& work) {
  const long long before = heap_bytes;
  heap_peak = before;
  work();
  return heap_peak - before;
}

}  // namespace polyplan::bench

void* operator new(std::size_t size) { return polyplan::bench::counted_allocation(size); }
void* operator new[](std::size_t size) { return polyplan::bench::counted_allocation(size); }
void operator delete(void* p) noexcept { polyplan::bench::counted_release(p); }
void operator delete[](void* p) noexcept { polyplan::bench::counted_release(p); }
void operator delete(void* p, std::size_t) noexcept { polyplan::bench::counted_release(p); }
void operator delete[](void* p, std::size_t) noexcept { polyplan::bench::counted_release(p); }
