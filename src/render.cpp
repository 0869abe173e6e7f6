#include "render.h"

#include <algorithm>
#include <cmath>

namespace rt {

// The image is the float quotient the PNGs have always been made from (sum times the
// reciprocal weight, in float); PixelEstimate's double mean is kept for the statistics, as
// changing either would change output bytes.
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

double relative_noise(const std::vector<PixelAccum>& accum) {
  double sum = 0;
  for (const PixelAccum& a : accum) {
    const PixelEstimate e = estimate_pixel(a);
    if (e.n < 2) return 0;
    for (int c = 0; c < 3; ++c) sum += e.var[c] / e.n / (e.mean[c] * e.mean[c] + 1.0);
  }
  return accum.empty() ? 0 : std::sqrt(sum / (3.0 * accum.size()));
}

}  // namespace rt
