// Per-pixel moment files: what a render knows about each pixel's distribution (sample
// count, mean and variance of the unclamped radiance) plus the deterministic facts of each
// pixel's first sample, stored as OpenEXR so `compare` can test two renders statistically.
//
// File format (OpenEXR, scanline, ZIP compression, one part; version attribute rt.moments 1):
//   R, G, B          FLOAT  mean radiance per channel (sum / filter weight; 255 = white,
//                           unclamped), so any EXR viewer shows the render
//   var.R/G/B        FLOAT  unbiased sample variance of one sample's radiance per channel,
//                           sum (x - mean)^2 / (n - 1); 0 when n < 2. The variance of the
//                           mean is var / n (an overestimate under stratified sampling)
//   n                UINT   samples in the pixel (the same for the three channels)
//   first.t          FLOAT  distance along the first sample's camera ray to its hit; +inf
//                           when it hit nothing
//   first.instance   UINT   instance index of that hit; 4294967295 when it hit nothing
//   first.primitive  UINT   triangle/sphere index within the instance; 4294967295 likewise
//   first.N.X/Y/Z    FLOAT  shading normal at that hit (facing as modelled); 0 on a miss
// Header attributes: rt.moments (int, 1), rt.seed (int), rt.spp (int), rt.filter
// ("box"|"gaussian"), rt.device (string), rt.scene (string), rt.camera (int); a partial
// render's file also rt:samples (string, "<spp> of <asked>", io/partial_mark.h).
// With the box filter (default) every sample has weight 1, so R/G/B is the plain sample
// mean the statistical tests assume; with the Gaussian filter it is a weighted mean and
// the variance is only approximate, which `compare` refuses unless told otherwise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "integrator/render.h"

namespace rt {

struct MomentInfo {
  uint32_t seed = 0;
  int spp = 0;
  std::string filter = "box";
  std::string device;
  std::string scene;
  int camera = 0;
  std::string samples_mark;  // A partial render's "<spp> of <asked>" (io/partial_mark.h).
};

struct MomentImage {
  int width = 0, height = 0;
  MomentInfo info;
  std::vector<float> mean;          // 3 per pixel, row-major, top row first
  std::vector<float> var;           // 3 per pixel
  std::vector<uint32_t> count;      // 1 per pixel
  std::vector<float> first_t;       // 1 per pixel, +inf on a miss
  std::vector<int32_t> instance;    // 1 per pixel, -1 on a miss
  std::vector<int32_t> primitive;   // 1 per pixel, -1 on a miss
  std::vector<float> normal;        // 3 per pixel

  size_t pixels() const { return static_cast<size_t>(width) * height; }
};

// Per-pixel moments of a finished render. Sums are taken in double from the device's
// float accumulators, so the variance is as exact as the float sums allow.
MomentImage moments_from_render(const RenderResult& r, const MomentInfo& info);

// The moment file written beside a PNG: "<dir>/<name>.png" -> "<dir>/<name>.moments.exr".
std::string moments_path_for(const std::string& png_path);

// Writes atomically (temporary file in the same directory, then rename). Throws
// std::runtime_error("<path>: cannot write moments: <reason>").
void write_moments(const std::string& path, const MomentImage& m);

// Throws std::runtime_error("<path>: cannot read moments: <reason>") when the file is not
// an EXR with the channels above.
MomentImage read_moments(const std::string& path);

}  // namespace rt
