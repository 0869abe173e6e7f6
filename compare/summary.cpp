#include "summary.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include "image/read_hdr.h"
#include "inputs.h"

namespace cmp {
namespace {

std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return std::string("  ") + buf + "\n";
}

// Range, non-finite counts and mean of `channels` interleaved channels, named by `names`.
std::string channel_figures(const std::vector<float>& v, int channels, const char* names) {
  std::string s;
  for (int c = 0; c < channels; ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
    size_t nan = 0, inf = 0, finite = 0;
    for (size_t i = c; i < v.size(); i += channels) {
      float x = v[i];
      if (std::isnan(x)) {
        ++nan;
      } else if (std::isinf(x)) {
        ++inf;
      } else {
        lo = std::min(lo, static_cast<double>(x));
        hi = std::max(hi, static_cast<double>(x));
        sum += x;
        ++finite;
      }
    }
    if (finite == 0)
      s += line("%c: no finite value, NaN %zu, Inf %zu", names[c], nan, inf);
    else
      s += line("%c: range [%.6g, %.6g], mean %.6g, NaN %zu, Inf %zu", names[c], lo, hi,
                sum / finite, nan, inf);
  }
  return s;
}

std::string moment_figures(const rt::MomentImage& m, const std::string& path) {
  uint32_t lo = std::numeric_limits<uint32_t>::max(), hi = 0;
  double sum = 0;
  for (uint32_t n : m.count) {
    lo = std::min(lo, n);
    hi = std::max(hi, n);
    sum += n;
  }
  if (m.count.empty()) lo = 0;
  std::string s = line("moments %s: %d spp, seed %u, filter %s, device %s, scene %s, camera %d",
                       path.c_str(), m.info.spp, m.info.seed, m.info.filter.c_str(),
                       m.info.device.c_str(), m.info.scene.c_str(), m.info.camera);
  s += line("samples per pixel: min %u, mean %.4g, max %u", lo,
            m.count.empty() ? 0.0 : sum / m.count.size(), hi);
  s += "  mean radiance (255 = white):\n" + channel_figures(m.mean, 3, "RGB");
  s += "  per-sample variance:\n" + channel_figures(m.var, 3, "RGB");
  return s;
}

}  // namespace

std::string summarise(const std::string& path) {
  std::string s = "summary: " + path + "\n";
  if (is_moment_file(path)) {
    Side side = load_side(path, false);
    s += line("%dx%d, moment file", side.moments.width, side.moments.height);
    return s + moment_figures(side.moments, path);
  }
  if (rt::has_hdr_extension(path)) {
    rt::ImageF img = rt::read_hdr_image(path);
    s += line("%dx%d, %d channel%s, linear radiance", img.width, img.height, img.channels,
              img.channels == 1 ? "" : "s");
    const char* names = img.channels == 1 ? "Y" : "RGBA";
    return s + channel_figures(img.pixels, img.channels, names);
  }
  std::string note;
  Side side = load_side(path, true, &note);
  s += line("%dx%d, 8-bit RGB PNG", side.image.width, side.image.height);
  std::vector<float> levels(side.image.rgb.begin(), side.image.rgb.end());
  s += channel_figures(levels, 3, "RGB");
  if (side.has_moments) return s + moment_figures(side.moments, side.moments_path);
  return s + (note.empty() ? line("no moment file beside it") : line("%s", note.c_str()));
}

}  // namespace cmp
