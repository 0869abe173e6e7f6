// Minimal fork-join helpers for the host's setup work (the BVH build and the copies around
// it). Work is cut into pieces fixed by the data alone, never by the thread count, so that
// whatever runs them, every piece computes the same bytes.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace rt {

// The thread count that `requested` stands for: itself when positive, else every core.
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// An atomic alone on its cache line, for a value several threads write.
template <class T>
struct alignas(64) PaddedAtomic {
  std::atomic<T> value{0};
};

// Runs fn(0) ... fn(count - 1) on up to `threads` threads (the caller's included), each
// index exactly once, in no particular order.
template <class Fn>
void parallel_for(int count, int threads, Fn fn) {
  threads = std::max(1, std::min(threads, count));
  if (threads == 1) {
    for (int i = 0; i < count; ++i) fn(i);
    return;
  }
  // The counter has a cache line of its own and each thread its own copy of count and fn:
  // read through references into this frame, they would share lines with what the calling
  // thread spills there as it works, and each of its writes would cost the others a miss.
  PaddedAtomic<int> next;
  auto work = [&next, count, fn] {
    for (int i; (i = next.value.fetch_add(1)) < count;) fn(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// The pieces parallel_ranges cuts [0, n) into.
inline size_t piece_count(size_t n, size_t grain) {
  return std::max<size_t>(1, (n + grain - 1) / grain);
}

// Cuts [0, n) into piece_count(n, grain) pieces of about `grain` elements, fixed by n and
// grain alone, and runs fn(piece, begin, end) for each on up to `threads` threads.
template <class Fn>
void parallel_ranges(size_t n, size_t grain, int threads, Fn fn) {
  const size_t pieces = piece_count(n, grain);
  parallel_for(static_cast<int>(pieces), threads,
               [&](int p) { fn(static_cast<size_t>(p), n * p / pieces, n * (p + 1) / pieces); });
}

}  // namespace rt
