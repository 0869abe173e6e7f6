// A perceptual colour map for difference images: viridis (van der Walt and Smith, the
// default of matplotlib), uniform in lightness from dark blue (0) to yellow (1), readable
// in grey and by the colour-blind. Ten stops of matplotlib's table, linearly interpolated:
// the steps between stops are smaller than the eye tells apart on a map.
#pragma once

#include <cstdint>
#include <vector>

#include "io/png_io.h"

namespace cmp {

// The colour of t in [0, 1] (clamped; NaN counts as 0).
void viridis(double t, uint8_t rgb[3]);

// values[i] / scale through the colour map, one pixel per value (scale > 0).
rt::Image8 colour_map(int w, int h, const std::vector<float>& values, double scale);

// A horizontal bar of the map, `w` x `h` pixels, 0 on the left: the legend beside a map.
rt::Image8 colour_bar(int w, int h);

}  // namespace cmp
