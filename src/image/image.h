// A decoded image in memory, whatever file it came from: the one type that texture,
// environment-map and tone-mapping code exchange. Readers live beside this file, one per
// family of formats (read_ldr: PNG, JPEG...; read_hdr: OpenEXR, Radiance HDR).
#pragma once

#include <string>
#include <vector>

namespace rt {

struct ImageF {
  int width = 0, height = 0;
  int channels = 3;  // 1 (grey), 3 (RGB) or 4 (RGBA).
  // Row-major, top row first, `channels` values per pixel. Low-dynamic-range files keep
  // their stored values on their own scale (0..255 for 8-bit, 0..65535 for 16-bit; see
  // `max_value`); high-dynamic-range files hold linear radiance.
  std::vector<float> pixels;
  float max_value = 255.0f;  // The largest value the file's encoding can hold (HDR: 0).

  size_t size() const { return static_cast<size_t>(width) * height; }
  float at(int x, int y, int c) const {
    return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
  }
};

}  // namespace rt
