#include "device/cpu/cpu_device.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include "util/parallel_for.h"

namespace rt {

CpuDevice::CpuDevice(int threads) : threads_(resolve_threads(threads)) {}

// The film lives in host memory, beside the caller's outputs; the scene arrays are
// already allocated.
void CpuDevice::check_memory(const MemoryNeed& need) const {
  const uint64_t pixels = static_cast<uint64_t>(need.width) * need.height;
  const uint64_t limit = available_host_memory();
  check_memory_limit(need, pixels * kFilmBytesPerPixel + need.host_bytes, limit, "memory",
                     "the " + format_bytes(limit) + " available");
}

DeviceLoadInfo CpuDevice::load(const FlatScene& flat, const KernelConfig& kernel) {
  if (!supports_bvh_width(kernel.bvh_width))
    throw std::runtime_error("cpu-reference: the scene was prepared for " +
                             std::to_string(kernel.bvh_width) +
                             "-wide BVH nodes, but the CPU "
                             "reference is compiled for " +
                             std::to_string(RT_BVH_WIDTH));
  // The traversal's stack is the static bound; sized_for_scene refuses deeper trees.
  sized_for_scene(kernel, flat);
  flat_ = &flat;
  accumulate_ = select_cpu_kernel(kernel.double_precision).accumulate;
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
  const CpuPixelFunction accumulate = accumulate_;
  // Threads take chunks of pixels, not rows, so a pass over a band of a few rows still
  // keeps every thread busy to its end. Each pixel is taken by one thread, which adds its
  // samples in order: the image does not depend on the thread count. A chunk gives every
  // thread about 16 (its last one then a small part of its work), from 16 to 256 pixels:
  // long runs of film records let each core's prefetcher stay ahead, where short chunks
  // leave it restarting on every chunk.
  const size_t chunk = std::clamp<size_t>(count / (16 * static_cast<size_t>(threads_)), 16, 256);
  const int chunks = static_cast<int>((count + chunk - 1) / chunk);
  // Each thread copies the loop's values (parallel_for copies fn): read through references
  // into this frame, they would share cache lines with what the calling thread writes.
  PaddedAtomic<uint64_t> rays;
  auto render_chunk = [&rays, chunk, first, count, width, accumulate, sd = &view_,
                       accum = accum_.data(), primary = primary_.data(), s0 = work.sample_begin,
                       s1 = work.sample_end](int k) {
    // The pixel's coordinates advance with it: one division per chunk.
    const size_t c = static_cast<size_t>(k) * chunk, begin = first + c;
    int y = static_cast<int>(begin / width);
    int x = static_cast<int>(begin - size_t(y) * width);
    uint64_t mine = 0;
    for (size_t i = begin, end = first + std::min(count, c + chunk); i < end; ++i) {
      const uint32_t before = accum[i].rays;
      accumulate(sd, x, y, s0, s1, &accum[i], &primary[i]);
      mine += accum[i].rays - before;
      if (++x == width) x = 0, ++y;
    }
    rays.value += mine;
  };
  parallel_for(chunks, threads_, render_chunk);
  return rays.value.load();
}

void CpuDevice::write_film(const std::vector<PixelAccum>& accum,
                           const std::vector<PrimaryInfo>& primary) {
  if (accum.size() != accum_.size() || primary.size() != primary_.size())
    throw std::runtime_error("the saved film has " + std::to_string(accum.size()) +
                             " pixels, the camera " + std::to_string(accum_.size()));
  accum_ = accum;
  primary_ = primary;
}

}  // namespace rt
