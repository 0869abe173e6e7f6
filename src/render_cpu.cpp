#include <atomic>
#include <chrono>
#include <thread>

#include "render.h"

namespace rt {

std::vector<float> RenderResult::rgb() const {
  std::vector<float> out(accum.size() * 3);
  for (size_t i = 0; i < accum.size(); ++i) {
    const float4& s = accum[i].sum;
    float inv = s.w > 0 ? 1.0f / s.w : 0.0f;
    out[i * 3 + 0] = s.x * inv;
    out[i * 3 + 1] = s.y * inv;
    out[i * 3 + 2] = s.z * inv;
  }
  return out;
}

uint64_t RenderResult::nonfinite() const {
  uint64_t n = 0;
  for (const PixelAccum& a : accum) n += a.nonfinite;
  return n;
}

RenderResult render_cpu(const FlatScene& flat, int threads, Progress& progress) {
  const Camera& cam = flat.header.camera;
  RenderResult r;
  r.width = cam.width;
  r.height = cam.height;
  r.accum.assign(static_cast<size_t>(cam.width) * cam.height, PixelAccum{});
  r.primary.assign(r.accum.size(), PrimaryInfo{});
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  SceneData sd = flat.view();
  std::atomic<int> next_row{0};
  auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (int y; (y = next_row++) < cam.height;) {
      uint64_t rays = 0;
      for (int x = 0; x < cam.width; ++x) {
        size_t i = static_cast<size_t>(y) * cam.width + x;
        AccumulatePixel(&sd, x, y, 0, cam.samples, &r.accum[i], &r.primary[i]);
        rays += r.accum[i].rays;
      }
      progress.add(static_cast<uint64_t>(cam.width) * cam.samples, rays);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.samples = static_cast<uint64_t>(r.accum.size()) * cam.samples;
  for (auto& a : r.accum) r.rays += a.rays;
  return r;
}

}  // namespace rt
