#include "render.h"

#include <algorithm>
#include <cmath>

#include "image/tonemap.h"

namespace rt {

// The image is the float quotient the PNGs have always been made from (sum times the
// reciprocal weight, in float); PixelEstimate's double mean is kept for the statistics, as
// changing either would change output bytes.
std::vector<float> RenderResult::rgb() const { return film_rgb(accum); }

std::vector<float> film_rgb(const std::vector<PixelAccum>& accum) {
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

PixelEstimate estimate_pixel(const PixelAccum& a) {
  PixelEstimate e;
  const double sum[3] = {a.sum.x, a.sum.y, a.sum.z};
  const double sq[3] = {a.sum_sq.x, a.sum_sq.y, a.sum_sq.z};
  const double w = a.sum.w;
  e.n = a.sum_sq.w;
  for (int c = 0; c < 3; ++c) {
    e.mean[c] = w > 0 ? sum[c] / w : 0.0;
    // From the raw sums; rounding can push it slightly below zero.
    double var = e.n > 1 ? (sq[c] - e.n * e.mean[c] * e.mean[c]) / (e.n - 1) : 0.0;
    e.var[c] = std::max(0.0, var);
  }
  return e;
}

double relative_noise(const std::vector<PixelAccum>& accum, int width, double floor) {
  if (accum.empty() || width <= 0) return 0;
  const int height = static_cast<int>(accum.size() / static_cast<size_t>(width));
  const double floor2 = floor * floor;
  std::vector<PixelEstimate> e(accum.size());
  for (size_t i = 0; i < accum.size(); ++i) {
    e[i] = estimate_pixel(accum[i]);
    if (e[i].n < 2) return 0;
  }
  constexpr int kTile = 8;
  double sum = 0;
  for (int ty = 0; ty < height; ty += kTile)
    for (int tx = 0; tx < width; tx += kTile)
      for (int c = 0; c < 3; ++c) {
        const int y1 = std::min(height, ty + kTile), x1 = std::min(width, tx + kTile);
        double var = 0, mean2 = 0;  // Of the tile: sums of var / n and of mean^2 + floor^2.
        for (int y = ty; y < y1; ++y)
          for (int x = tx; x < x1; ++x) {
            const PixelEstimate& p = e[static_cast<size_t>(y) * width + x];
            var += p.var[c] / p.n;
            mean2 += p.mean[c] * p.mean[c] + floor2;
          }
        const double tile = var / mean2;
        for (int y = ty; y < y1; ++y)
          for (int x = tx; x < x1; ++x) {
            const PixelEstimate& p = e[static_cast<size_t>(y) * width + x];
            sum += p.var[c] > 0 ? p.var[c] / p.n / (p.mean[c] * p.mean[c] + floor2) : tile;
          }
      }
  return std::sqrt(sum / (3.0 * static_cast<double>(accum.size())));
}

double relative_mse(const std::vector<float>& img, const std::vector<float>& ref, double floor) {
  const double floor2 = floor * floor;
  double s = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    const double d = static_cast<double>(img[i]) - ref[i];
    s += d * d / (static_cast<double>(ref[i]) * ref[i] + floor2);
  }
  return ref.empty() ? 0 : s / static_cast<double>(ref.size());
}

double noise_floor(const std::vector<float>& rgb, double tonemap_key) {
  const size_t n = rgb.size() / 3;
  if (!(tonemap_key > 0) || n == 0) return 1.0;
  // The photographic operator's own log-average (src/image/tonemap.h), over the film.
  ImageF film;
  film.width = static_cast<int>(n);
  film.height = 1;
  film.pixels = rgb;
  return LogAverageLuminance(film) / (tonemap_key * 255.0);
}

double noise_floor(const std::vector<PixelAccum>& accum, double tonemap_key) {
  return tonemap_key > 0 ? noise_floor(film_rgb(accum), tonemap_key) : 1.0;
}

}  // namespace rt
