// Images of a comparison for a person to look at (PNG, one pixel per image pixel; a tile's
// value fills its tile).
//   difference: 128 + gain * (B - A) per channel, so mid-gray means equal, brighter means
//               B is brighter
//   p-value:    gray level 230 * min(1, log10(p) / log10(per-test level)) of the smallest
//               p of the cell's channels (black: p = 1, near white: at the rejection
//               level); red: rejected; magenta: deterministic failure; dark blue: not
//               tested (zero variance and equal means)
//   mask:       white where the cell fails, black elsewhere
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "family.h"
#include "io/png_io.h"

namespace cmp {

rt::Image8 difference_map(const Family& f, double gain);
rt::Image8 pvalue_map(const Family& f, const Verdict& v);
rt::Image8 mask_map(const Family& f);

// A gray image of per-pixel values scaled by `gain` (clamped), and a mask of flags.
rt::Image8 gray_map(int w, int h, const std::vector<float>& values, double gain);
rt::Image8 mask_map(int w, int h, const std::vector<uint8_t>& flags);

// Writes <dir>/<prefix>-<name>.png for each non-empty image and prints the paths.
void write_map(const std::string& dir, const std::string& prefix, const std::string& name,
               const rt::Image8& image);

}  // namespace cmp
