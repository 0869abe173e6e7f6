#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
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

double relative_noise(const std::vector<PixelAccum>& accum) {
  double sum = 0;
  for (const PixelAccum& a : accum) {
    double n = a.sum_sq.w;
    if (n < 2) return 0;
    const double mean[3] = {a.sum.x / a.sum.w, a.sum.y / a.sum.w, a.sum.z / a.sum.w};
    const double sq[3] = {a.sum_sq.x, a.sum_sq.y, a.sum_sq.z};
    for (int c = 0; c < 3; ++c) {
      double var = std::max(0.0, (sq[c] / n - mean[c] * mean[c]) * n / (n - 1));
      sum += var / n / (mean[c] * mean[c] + 1.0);
    }
  }
  return accum.empty() ? 0 : std::sqrt(sum / (3.0 * accum.size()));
}

RenderResult render_cpu(const FlatScene& flat, int threads, Progress& progress,
                        const StopRule& stop) {
  using Clock = std::chrono::steady_clock;
  const Camera& cam = flat.header.camera;
  RenderResult r;
  r.width = cam.width;
  r.height = cam.height;
  r.accum.assign(static_cast<size_t>(cam.width) * cam.height, PixelAccum{});
  r.primary.assign(r.accum.size(), PrimaryInfo{});
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  SceneData sd = flat.view();
  auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  // Passes grow geometrically (1, 2, 4, ... samples) so a stop rule is checked often at
  // first and rarely later; without a stop rule one pass takes every sample.
  bool stopping = stop.time_limit_s > 0 || stop.noise_target > 0;
  int done = 0;
  for (int pass = stopping ? 1 : cam.samples; done < cam.samples; pass *= 2) {
    int s0 = done, s1 = std::min(cam.samples, done + pass);
    std::atomic<int> next_row{0};
    auto worker = [&] {
      for (int y; (y = next_row++) < cam.height;) {
        uint64_t rays = 0;
        for (int x = 0; x < cam.width; ++x) {
          size_t i = static_cast<size_t>(y) * cam.width + x;
          uint32_t before = r.accum[i].rays;
          AccumulatePixel(&sd, x, y, s0, s1, &r.accum[i], &r.primary[i]);
          rays += r.accum[i].rays - before;
        }
        progress.add(static_cast<uint64_t>(cam.width) * (s1 - s0), rays);
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    done = s1;
    double t = elapsed();
    // Stop when the next pass (twice this one) would overrun the budget, or when the
    // image is quiet enough.
    if (stop.time_limit_s > 0 && done < cam.samples &&
        t * (1.0 + 2.0 * (s1 - s0) / done) > stop.time_limit_s)
      break;
    if (stop.noise_target > 0 && done >= 2 && relative_noise(r.accum) < stop.noise_target) break;
  }
  r.seconds = elapsed();
  r.spp = done;
  r.samples = static_cast<uint64_t>(r.accum.size()) * done;
  for (auto& a : r.accum) r.rays += a.rays;
  return r;
}

}  // namespace rt
