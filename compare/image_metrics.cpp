// Image comparison metrics. Sums are accumulated in integers where possible so that results on
// small hand-made images are exact and independent of summation order.
#include "image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace rt {
namespace {

std::string size_text(const Image8& img) {
  return std::to_string(img.width) + "x" + std::to_string(img.height);
}

void check_buffer(const Image8& img, const char* what) {
  if (img.width < 0 || img.height < 0 ||
      img.rgb.size() != static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 3) {
    throw std::invalid_argument(std::string(what) + ": " + size_text(img) + " image has " +
                                std::to_string(img.rgb.size()) + " bytes of RGB");
  }
}

void check_same_size(const Image8& a, const Image8& b, const char* what) {
  check_buffer(a, what);
  check_buffer(b, what);
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(std::string(what) + ": image sizes differ: " + size_text(a) +
                                " vs " + size_text(b));
  }
}

}  // namespace

ImageDiff diff_images(const Image8& a, const Image8& b, int threshold) {
  check_same_size(a, b, "diff_images");
  ImageDiff diff;
  const size_t pixels = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  if (pixels == 0) {
    diff.psnr = std::numeric_limits<double>::infinity();
    diff.frac_identical = 1;
    return diff;
  }

  // 64-bit sums: 255^2 * 3 per pixel stays exact for any image that fits in memory.
  uint64_t sum_abs = 0, sum_sq = 0;
  size_t over = 0, identical = 0;
  int max_abs = 0;
  for (size_t p = 0; p < pixels; ++p) {
    int pixel_max = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int{a.rgb[p * 3 + c]} - int{b.rgb[p * 3 + c]});
      sum_abs += static_cast<uint64_t>(d);
      sum_sq += static_cast<uint64_t>(d * d);
      pixel_max = std::max(pixel_max, d);
    }
    max_abs = std::max(max_abs, pixel_max);
    if (pixel_max > threshold) ++over;
    if (pixel_max == 0) ++identical;
  }

  const double samples = static_cast<double>(pixels) * 3;
  diff.mae = static_cast<double>(sum_abs) / samples;
  diff.rmse = std::sqrt(static_cast<double>(sum_sq) / samples);
  diff.psnr =
      diff.rmse == 0 ? std::numeric_limits<double>::infinity() : 20 * std::log10(255 / diff.rmse);
  diff.frac_over = static_cast<double>(over) / static_cast<double>(pixels);
  diff.max_abs = max_abs;
  diff.frac_identical = static_cast<double>(identical) / static_cast<double>(pixels);
  return diff;
}

Image8 downsample(const Image8& img, int k) {
  check_buffer(img, "downsample");
  if (k < 1)
    throw std::invalid_argument("downsample: factor must be >= 1, got " + std::to_string(k));
  Image8 out;
  out.width = img.width / k;
  out.height = img.height / k;
  out.rgb.resize(static_cast<size_t>(out.width) * out.height * 3);
  const double area = static_cast<double>(k) * k;
  for (int oy = 0; oy < out.height; ++oy) {
    for (int ox = 0; ox < out.width; ++ox) {
      for (int c = 0; c < 3; ++c) {
        double sum = 0;  // Integer-valued and far below 2^53, so exact.
        for (int y = oy * k; y < (oy + 1) * k; ++y) {
          const size_t row = static_cast<size_t>(y) * img.width;
          for (int x = ox * k; x < (ox + 1) * k; ++x) sum += img.rgb[(row + x) * 3 + c];
        }
        const size_t o = (static_cast<size_t>(oy) * out.width + ox) * 3 + c;
        out.rgb[o] = static_cast<uint8_t>(std::lround(sum / area));
      }
    }
  }
  return out;
}

Image8 difference_image(const Image8& a, const Image8& b, double gain) {
  check_same_size(a, b, "difference_image");
  if (!(gain >= 0)) {
    throw std::invalid_argument("difference_image: gain must be >= 0, got " + std::to_string(gain));
  }
  Image8 out;
  out.width = a.width;
  out.height = a.height;
  out.rgb.resize(a.rgb.size());
  const size_t pixels = a.rgb.size() / 3;
  for (size_t p = 0; p < pixels; ++p) {
    int d = 0;
    for (int c = 0; c < 3; ++c) {
      d = std::max(d, std::abs(int{a.rgb[p * 3 + c]} - int{b.rgb[p * 3 + c]}));
    }
    // d == 0 is special-cased because gain may be +infinity, and 0 * inf is NaN.
    const double scaled = d == 0 ? 0.0 : std::min(255.0, d * gain);
    const uint8_t v = static_cast<uint8_t>(std::lround(scaled));
    out.rgb[p * 3] = out.rgb[p * 3 + 1] = out.rgb[p * 3 + 2] = v;
  }
  return out;
}

}  // namespace rt
