#include "device/cpu_device.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "device/cpu_kernel.h"
#include "util/parallel_for.h"

namespace rt {

CpuDevice::CpuDevice(int threads) : threads_(resolve_threads(threads)) {}

// The film lives in host memory, beside the caller's outputs; the scene arrays are
// already allocated.
void CpuDevice::check_memory(const FlatScene& flat, uint64_t host_bytes) const {
  const uint64_t pixels =
      static_cast<uint64_t>(flat.header.camera.width) * flat.header.camera.height;
  const uint64_t limit = available_host_memory();
  check_memory_limit(flat, pixels * kFilmBytesPerPixel + host_bytes, limit, "memory",
                     "the " + format_bytes(limit) + " available");
}

DeviceLoadInfo CpuDevice::load(const FlatScene& flat) {
  flat_ = &flat;
  view_ = flat.view();
  const size_t pixels = static_cast<size_t>(flat.header.camera.width) * flat.header.camera.height;
  accum_.assign(pixels, PixelAccum{});
  primary_.assign(pixels, PrimaryInfo{});
  return {};
}

uint64_t CpuDevice::render(const RenderWork& work) {
  const int width = flat_->header.camera.width;
  const size_t first = static_cast<size_t>(work.row_begin) * width;
  const size_t count = static_cast<size_t>(work.rows()) * width;
  const CpuPixelFunction accumulate = select_cpu_kernel(flat_->double_precision).accumulate;
  // Threads take chunks of pixels, not rows, so a pass over a band of a few rows still
  // keeps every thread busy to its end. Each pixel is taken by one thread, which adds its
  // samples in order: the image does not depend on the thread count. A chunk gives every
  // thread about 16 (its last one then a small part of its work), from 16 to 256 pixels:
  // long runs of film records let each core's prefetcher stay ahead (tap_0200's camera rays
  // on two threads took 6 % more CPU time with 16-pixel chunks than with 256).
  const size_t chunk =
      std::clamp<size_t>(count / (16 * static_cast<size_t>(std::max(1, threads_))), 16, 256);
  // What the threads write, each on a cache line of its own; everything else a worker reads
  // it holds by value. Read through references into this frame, those values shared cache
  // lines with the locals the calling thread spills at every pixel, and each such write cost
  // the other thread a miss per pixel (tap_0200's camera rays on two threads: 8 % more rays
  // per CPU-second once apart).
  struct alignas(64) Next {
    std::atomic<size_t> offset{0};
  } next;
  struct alignas(64) Rays {
    std::atomic<uint64_t> total{0};
  } rays;
  auto worker = [&next, &rays, chunk, first, count, width, accumulate, sd = &view_,
                 accum = accum_.data(), primary = primary_.data(), s0 = work.sample_begin,
                 s1 = work.sample_end] {
    uint64_t mine = 0;
    for (size_t c; (c = next.offset.fetch_add(chunk)) < count;) {
      // The pixel's coordinates advance with it: one division per chunk, not two per pixel.
      const size_t begin = first + c;
      int y = static_cast<int>(begin / width), x = static_cast<int>(begin - size_t(y) * width);
      for (size_t i = begin, end = first + std::min(count, c + chunk); i < end; ++i) {
        const uint32_t before = accum[i].rays;
        accumulate(sd, x, y, s0, s1, &accum[i], &primary[i]);
        mine += accum[i].rays - before;
        if (++x == width) x = 0, ++y;
      }
    }
    rays.total += mine;
  };
  const int helpers = static_cast<int>(std::min<size_t>(threads_, (count + chunk - 1) / chunk)) - 1;
  std::vector<std::thread> pool;
  for (int t = 0; t < helpers; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return rays.total.load();
}

}  // namespace rt
