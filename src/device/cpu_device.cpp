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
  // samples in order: the image does not depend on the thread count.
  constexpr size_t kChunk = 16;
  std::atomic<size_t> next{0};
  std::atomic<uint64_t> rays{0};
  auto worker = [&] {
    uint64_t mine = 0;
    for (size_t c; (c = next.fetch_add(kChunk)) < count;) {
      // The pixel's coordinates advance with it: one division per chunk, not two per pixel.
      const size_t begin = first + c;
      int y = static_cast<int>(begin / width), x = static_cast<int>(begin - size_t(y) * width);
      for (size_t i = begin, end = first + std::min(count, c + kChunk); i < end; ++i) {
        const uint32_t before = accum_[i].rays;
        accumulate(&view_, x, y, work.sample_begin, work.sample_end, &accum_[i], &primary_[i]);
        mine += accum_[i].rays - before;
        if (++x == width) x = 0, ++y;
      }
    }
    rays += mine;
  };
  const int helpers =
      static_cast<int>(std::min<size_t>(threads_, (count + kChunk - 1) / kChunk)) - 1;
  std::vector<std::thread> pool;
  for (int t = 0; t < helpers; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return rays.load();
}

}  // namespace rt
