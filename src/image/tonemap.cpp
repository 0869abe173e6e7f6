#include "image/tonemap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rt {

Image8 TonemapPhotographic(const ImageF& hdr, const PhotographicParams& params) {
  if (hdr.channels != 3 && hdr.channels != 4)
    throw std::invalid_argument("tone mapping needs an RGB image, got " +
                                std::to_string(hdr.channels) + " channels");
  const size_t n = hdr.size();
  Image8 out;
  out.width = hdr.width;
  out.height = hdr.height;
  out.rgb.assign(n * 3, 0);
  if (n == 0) return out;
  std::vector<double> y(n);
  double log_sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const float* c = &hdr.pixels[i * hdr.channels];
    y[i] = Luminance(c[0], c[1], c[2]);
    // The small delta keeps black pixels (the background) from sending the sum to -inf.
    log_sum += std::log(1e-6 + y[i]);
  }
  const double scale = params.key / std::exp(log_sum / static_cast<double>(n));
  double white2 = 0.0;
  if (params.burn_percent > 0.0) {
    std::vector<double> sorted(n);
    for (size_t i = 0; i < n; ++i) sorted[i] = scale * y[i];
    size_t k = static_cast<size_t>(std::floor(n * (100.0 - params.burn_percent) / 100.0));
    k = std::min(k, n - 1);
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    white2 = sorted[k] * sorted[k];
  }
  const double inv_gamma = 1.0 / params.gamma;
  for (size_t i = 0; i < n; ++i) {
    if (!(y[i] > 0.0)) continue;  // Black (or invalid) stays black.
    double l = scale * y[i];
    double ld = white2 > 0.0 ? l * (1.0 + l / white2) / (1.0 + l) : l / (1.0 + l);
    const float* c = &hdr.pixels[i * hdr.channels];
    for (int k = 0; k < 3; ++k) {
      double v = ld * std::pow(std::max(0.0, static_cast<double>(c[k])) / y[i], params.saturation);
      v = std::min(1.0, std::max(0.0, v));
      out.rgb[i * 3 + k] = static_cast<uint8_t>(255.0 * std::pow(v, inv_gamma));
    }
  }
  return out;
}

}  // namespace rt
