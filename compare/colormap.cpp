#include "colormap.h"

#include <algorithm>
#include <cmath>

namespace cmp {
namespace {

// matplotlib's viridis at t = 0, 1/9, ..., 1 (R's viridisLite::viridis(10)).
constexpr uint8_t kStops[10][3] = {{68, 1, 84},    {72, 40, 120},  {62, 74, 137},  {49, 104, 142},
                                   {38, 130, 142}, {31, 158, 137}, {53, 183, 121}, {109, 205, 89},
                                   {180, 222, 44}, {253, 231, 37}};

}  // namespace

void viridis(double t, uint8_t rgb[3]) {
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  double x = t * 9;
  int i = std::min(8, static_cast<int>(x));
  double f = x - i;
  for (int c = 0; c < 3; ++c)
    rgb[c] =
        static_cast<uint8_t>(std::lround(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c])));
}

rt::Image8 colour_map(int w, int h, const std::vector<float>& values, double scale) {
  rt::Image8 img;
  img.width = w;
  img.height = h;
  img.rgb.assign(static_cast<size_t>(w) * h * 3, 0);
  for (size_t i = 0; i < values.size() && i * 3 < img.rgb.size(); ++i)
    viridis(values[i] / scale, &img.rgb[i * 3]);
  return img;
}

rt::Image8 colour_bar(int w, int h) {
  std::vector<float> ramp(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < ramp.size(); ++i)
    ramp[i] = w > 1 ? static_cast<float>(i % w) / (w - 1) : 0.0f;
  return colour_map(w, h, ramp, 1.0);
}

}  // namespace cmp
