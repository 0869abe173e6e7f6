// A regular subset of an image's 4x4 blocks, rendered with the CPU reference at a camera's
// full sample count and set beside a reference image, for the benchmarks that check the
// path tracer against the course's references (path_reference, subset_reference). The
// random numbers are keyed by pixel and sample alone, so a pixel of the subset is the very
// pixel a full render would make.
#pragma once

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "compare/image_metrics.h"
#include "device/cpu/cpu_kernel.h"
#include "image/tonemap.h"
#include "io/png_io.h"
#include "prepare/flat_scene.h"

namespace rt::bench {

// 4x4 blocks whose block coordinates are multiples of `stride`, packed into a compact image
// (rows of blocks); x(col), y(row) give the pixel of the full image.
struct Subset {
  int stride = 1, width = 0, height = 0;
  int x(int col) const { return (col / 4) * stride * 4 + col % 4; }
  int y(int row) const { return (row / 4) * stride * 4 + row % 4; }
};

// The subset of `cam` that `budget` samples (0: no limit, every block) render.
inline Subset make_subset(const Camera& cam, double budget) {
  double total = static_cast<double>(cam.width) * cam.height * cam.samples;
  Subset s;
  s.stride = budget > 0 ? std::max(1, static_cast<int>(std::ceil(std::sqrt(total / budget)))) : 1;
  s.width = ((cam.width / 4 + s.stride - 1) / s.stride) * 4;
  s.height = ((cam.height / 4 + s.stride - 1) / s.stride) * 4;
  return s;
}

inline ImageF blank(const Subset& sub) {
  ImageF out;
  out.width = sub.width;
  out.height = sub.height;
  out.max_value = 0;
  out.pixels.assign(out.size() * 3, 0.0f);
  return out;
}

// The subset's pixel means (linear radiance); with `variance`, also the variance of one
// sample's radiance per pixel and channel (unbiased, from the film's sum of squares), which
// gives the noise of the mean as variance / samples; with `instance`, the object instance
// each pixel's first camera ray hits (-1: none).
inline ImageF render_subset(const FlatScene& flat, const Subset& sub, ImageF* variance = nullptr,
                            std::vector<int>* instance = nullptr) {
  const Camera& cam = flat.header.camera;
  ImageF out = blank(sub);
  if (variance) *variance = blank(sub);
  if (instance) instance->assign(out.size(), -1);
  SceneData sd = flat.view();
  std::vector<std::thread> pool;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int row = t; row < sub.height; row += threads)
        for (int col = 0; col < sub.width; ++col) {
          PixelAccum acc{};
          PrimaryInfo info;
          accumulate_pixel_float(&sd, sub.x(col), sub.y(row), 0, cam.samples, &acc, &info);
          size_t pixel = static_cast<size_t>(row) * sub.width + col, i = pixel * 3;
          if (instance) (*instance)[pixel] = info.t > 0 ? info.instance : -1;
          const float sum[3] = {acc.sum.x, acc.sum.y, acc.sum.z};
          const float sq[3] = {acc.sum_sq.x, acc.sum_sq.y, acc.sum_sq.z};
          double n = acc.sum_sq.w;
          for (int k = 0; k < 3; ++k) {
            out.pixels[i + k] = sum[k] / acc.sum.w;
            if (variance && n > 1) {
              double mean = sum[k] / n;
              variance->pixels[i + k] =
                  static_cast<float>(std::max(0.0, (sq[k] / n - mean * mean) * n / (n - 1)));
            }
          }
        }
    });
  for (auto& th : pool) th.join();
  return out;
}

inline ImageF crop(const ImageF& img, const Subset& sub) {
  ImageF out = blank(sub);
  for (int row = 0; row < sub.height; ++row)
    for (int col = 0; col < sub.width; ++col)
      for (int k = 0; k < 3; ++k)
        out.pixels[(static_cast<size_t>(row) * sub.width + col) * 3 + k] =
            img.at(sub.x(col), sub.y(row), k);
  return out;
}

inline Image8 crop8(const Image8& img, const Subset& sub) {
  Image8 out;
  out.width = sub.width;
  out.height = sub.height;
  out.rgb.resize(static_cast<size_t>(sub.width) * sub.height * 3);
  for (int row = 0; row < sub.height; ++row)
    for (int col = 0; col < sub.width; ++col)
      for (int k = 0; k < 3; ++k)
        out.rgb[(static_cast<size_t>(row) * sub.width + col) * 3 + k] =
            img.rgb[(static_cast<size_t>(sub.y(row)) * img.width + sub.x(col)) * 3 + k];
  return out;
}

// Tone maps a (3-channel) image pixel by pixel with given image-wide statistics.
inline Image8 encode(const ImageF& img, const PhotographicScale& s, const PhotographicParams& p) {
  Image8 out;
  out.width = img.width;
  out.height = img.height;
  out.rgb.resize(img.size() * 3);
  for (size_t i = 0; i < img.size(); ++i) TonemapPixel(&img.pixels[i * 3], s, p, &out.rgb[i * 3]);
  return out;
}

// The figure of merit against a noisy reference: MAE in 8-bit levels after a 4x4 box
// downsample, which averages each block's per-pixel noise before the difference is taken.
inline double block_mae(const Image8& a, const Image8& b) {
  return diff_images(downsample(a, 4), downsample(b, 4)).mae;
}

inline double mean_luminance(const ImageF& img) {
  double sum = 0;
  for (size_t i = 0; i < img.size(); ++i)
    sum += Luminance(img.pixels[i * 3], img.pixels[i * 3 + 1], img.pixels[i * 3 + 2]);
  return sum / std::max<size_t>(1, img.size());
}

// The bias of `mine` against `ref` in standard errors: the mean over 4x4 blocks of the
// difference of their mean luminances, against its standard error from the blocks' own
// spread (the blocks are independent, so this covers both images' noise, whatever it is).
inline double block_bias_z(const ImageF& mine, const ImageF& ref) {
  std::vector<double> d;
  for (int by = 0; by < mine.height / 4; ++by)
    for (int bx = 0; bx < mine.width / 4; ++bx) {
      double sum = 0;
      for (int y = by * 4; y < by * 4 + 4; ++y)
        for (int x = bx * 4; x < bx * 4 + 4; ++x)
          sum += Luminance(mine.at(x, y, 0), mine.at(x, y, 1), mine.at(x, y, 2)) -
                 Luminance(ref.at(x, y, 0), ref.at(x, y, 1), ref.at(x, y, 2));
      d.push_back(sum / 16);
    }
  double mean = 0, var = 0;
  for (double v : d) mean += v / d.size();
  for (double v : d) var += (v - mean) * (v - mean) / (d.size() - 1);
  return mean / std::sqrt(var / d.size());
}

}  // namespace rt::bench
