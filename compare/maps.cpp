#include "maps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace cmp {
namespace {

rt::Image8 blank(int w, int h) {
  rt::Image8 img;
  img.width = w;
  img.height = h;
  img.rgb.assign(static_cast<size_t>(w) * h * 3, 0);
  return img;
}

uint8_t to_level(double v) { return static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

// Calls fn(pixel index, cell) for every pixel of the image.
template <typename Fn>
void for_pixels(const Family& f, Fn fn) {
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      fn(static_cast<size_t>(y) * f.width + x,
         f.cells[static_cast<size_t>(y / f.tile) * f.cells_x + x / f.tile]);
}

}  // namespace

rt::Image8 difference_map(const Family& f, double gain) {
  rt::Image8 img = blank(f.width, f.height);
  for_pixels(f, [&](size_t i, const Cell& cell) {
    for (int c = 0; c < 3; ++c) img.rgb[i * 3 + c] = to_level(128 + gain * cell.diff[c]);
  });
  return img;
}

rt::Image8 pvalue_map(const Family& f, const Verdict& v) {
  rt::Image8 img = blank(f.width, f.height);
  double scale = v.sidak_level > 0 && v.sidak_level < 1 ? std::log10(v.sidak_level) : -1;
  for_pixels(f, [&](size_t i, const Cell& cell) {
    uint8_t rgb[3] = {0, 0, 96};
    double min_p = 2;
    bool rejected = false, deterministic = false;
    for (int c = 0; c < 3; ++c) {
      rejected |= cell.rejected[c];
      deterministic |= cell.rejected[c] && cell.status[c] == CellStatus::kDeterministic;
      if (cell.status[c] == CellStatus::kTested) min_p = std::min(min_p, cell.p[c]);
    }
    if (deterministic) {
      rgb[0] = 255, rgb[1] = 0, rgb[2] = 255;
    } else if (rejected) {
      rgb[0] = 255, rgb[1] = 0, rgb[2] = 0;
    } else if (min_p <= 1) {
      double g = min_p > 0 ? std::min(1.0, std::log10(min_p) / scale) : 1.0;
      rgb[0] = rgb[1] = rgb[2] = to_level(230 * g);
    }
    std::copy(rgb, rgb + 3, &img.rgb[i * 3]);
  });
  return img;
}

rt::Image8 mask_map(const Family& f) {
  std::vector<uint8_t> flags(static_cast<size_t>(f.width) * f.height, 0);
  for_pixels(f, [&](size_t i, const Cell& cell) {
    flags[i] = cell.rejected[0] || cell.rejected[1] || cell.rejected[2];
  });
  return mask_map(f.width, f.height, flags);
}

rt::Image8 gray_map(int w, int h, const std::vector<float>& values, double gain) {
  rt::Image8 img = blank(w, h);
  for (size_t i = 0; i < values.size() && i * 3 < img.rgb.size(); ++i)
    img.rgb[i * 3] = img.rgb[i * 3 + 1] = img.rgb[i * 3 + 2] = to_level(gain * values[i]);
  return img;
}

rt::Image8 mask_map(int w, int h, const std::vector<uint8_t>& flags) {
  rt::Image8 img = blank(w, h);
  for (size_t i = 0; i < flags.size() && i * 3 < img.rgb.size(); ++i)
    if (flags[i]) img.rgb[i * 3] = img.rgb[i * 3 + 1] = img.rgb[i * 3 + 2] = 255;
  return img;
}

void write_map(const std::string& dir, const std::string& prefix, const std::string& name,
               const rt::Image8& image) {
  std::filesystem::create_directories(dir);
  std::string path = (std::filesystem::path(dir) / (prefix + "-" + name + ".png")).string();
  rt::write_png(path, image);
  std::printf("  wrote %s\n", path.c_str());
}

}  // namespace cmp
