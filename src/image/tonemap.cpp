#include "image/tonemap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rt {
namespace {

void CheckChannels(const ImageF& hdr) {
  if (hdr.channels != 3 && hdr.channels != 4)
    throw std::invalid_argument("tone mapping needs an RGB image, got " +
                                std::to_string(hdr.channels) + " channels");
}

double PixelLuminance(const ImageF& hdr, size_t i) {
  const float* c = &hdr.pixels[i * hdr.channels];
  return Luminance(c[0], c[1], c[2]);
}

}  // namespace

double LogAverageLuminance(const ImageF& hdr) {
  CheckChannels(hdr);
  const size_t n = hdr.size();
  if (n == 0) return 0.0;
  double log_sum = 0.0;
  // The small delta keeps black pixels (the background) from sending the sum to -inf.
  for (size_t i = 0; i < n; ++i) log_sum += std::log(1e-6 + PixelLuminance(hdr, i));
  return std::exp(log_sum / static_cast<double>(n));
}

PhotographicScale PhotographicStatistics(const ImageF& hdr, const PhotographicParams& params) {
  CheckChannels(hdr);
  PhotographicScale s;
  const size_t n = hdr.size();
  if (n == 0) return s;
  s.scale = params.key / LogAverageLuminance(hdr);
  if (params.burn_percent > 0.0) {
    std::vector<double> sorted(n);
    for (size_t i = 0; i < n; ++i) sorted[i] = s.scale * PixelLuminance(hdr, i);
    size_t k = static_cast<size_t>(std::floor(n * (100.0 - params.burn_percent) / 100.0));
    k = std::min(k, n - 1);
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    s.white2 = sorted[k] * sorted[k];
  }
  return s;
}

void TonemapPixel(const float rgb[3], const PhotographicScale& s, const PhotographicParams& params,
                  uint8_t out[3]) {
  double y = Luminance(rgb[0], rgb[1], rgb[2]);
  if (!(y > 0.0)) {  // Black (or invalid) stays black.
    out[0] = out[1] = out[2] = 0;
    return;
  }
  double l = s.scale * y;
  double ld = s.white2 > 0.0 ? l * (1.0 + l / s.white2) / (1.0 + l) : l / (1.0 + l);
  for (int k = 0; k < 3; ++k) {
    double v = ld * std::pow(std::max(0.0, static_cast<double>(rgb[k])) / y, params.saturation);
    v = std::min(1.0, std::max(0.0, v));
    out[k] = static_cast<uint8_t>(255.0 * std::pow(v, 1.0 / params.gamma));
  }
}

Image8 TonemapPhotographic(const ImageF& hdr, const PhotographicParams& params) {
  PhotographicScale s = PhotographicStatistics(hdr, params);
  Image8 out;
  out.width = hdr.width;
  out.height = hdr.height;
  out.rgb.assign(hdr.size() * 3, 0);
  for (size_t i = 0; i < hdr.size(); ++i)
    TonemapPixel(&hdr.pixels[i * hdr.channels], s, params, &out.rgb[i * 3]);
  return out;
}

}  // namespace rt
