#include "inputs.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace cmp {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

rt::Image8 image_of_means(const rt::MomentImage& m) {
  rt::Image8 img;
  img.width = m.width;
  img.height = m.height;
  img.rgb.resize(m.mean.size());
  for (size_t i = 0; i < m.mean.size(); ++i) {
    float v = std::isnan(m.mean[i]) ? 0.0f : std::clamp(m.mean[i], 0.0f, 255.0f);
    img.rgb[i] = static_cast<uint8_t>(std::lround(v));
  }
  return img;
}

}  // namespace

bool is_moment_file(const std::string& path) { return ends_with(path, ".moments.exr"); }

Side load_side(const std::string& path, bool with_moments, std::string* note) {
  Side s;
  s.path = path;
  if (is_moment_file(path)) {
    s.moments = rt::read_moments(path);
    s.has_moments = true;
    s.moments_path = path;
    s.image = image_of_means(s.moments);
    return s;
  }
  s.image = rt::read_png(path);
  if (!with_moments || !ends_with(path, ".png")) return s;
  std::string mp = rt::moments_path_for(path);
  std::error_code ec;
  if (!std::filesystem::exists(mp, ec)) return s;
  rt::MomentImage m = rt::read_moments(mp);
  if (m.width != s.image.width || m.height != s.image.height) {
    if (note)
      *note += mp + " is " + std::to_string(m.width) + "x" + std::to_string(m.height) + ", " +
               path + " " + std::to_string(s.image.width) + "x" + std::to_string(s.image.height) +
               ": moments left out. ";
    return s;
  }
  s.moments = std::move(m);
  s.has_moments = true;
  s.moments_path = mp;
  return s;
}

void require_same_size(const std::string& a, int wa, int ha, const std::string& b, int wb, int hb) {
  if (wa == wb && ha == hb) return;
  throw std::runtime_error(a + " is " + std::to_string(wa) + "x" + std::to_string(ha) + ", " + b +
                           " is " + std::to_string(wb) + "x" + std::to_string(hb) +
                           ": the images must be the same size");
}

}  // namespace cmp
