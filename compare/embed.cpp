#include "embed.h"

#include <stdlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/file_util.h"

namespace cmp {

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint32_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= bytes[i + 2];
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

std::string png_data_uri(const rt::Image8& image) {
  // rt::write_png is the project's one PNG encoder; it writes files only, so the bytes
  // come back through a directory no other process knows the name of.
  std::string tmpl = (std::filesystem::temp_directory_path() / "compare-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary directory");
  std::filesystem::path dir(tmpl);
  std::vector<uint8_t> bytes;
  int err = 0;
  try {
    rt::write_png((dir / "image.png").string(), image);
    err = rt::read_file((dir / "image.png").string(), &bytes);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    throw;
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  if (err) throw std::runtime_error("cannot read back an encoded PNG: " + rt::errno_text(err));
  return "data:image/png;base64," + base64(bytes);
}

rt::Image8 crop(const rt::Image8& image, int x, int y, int w, int h) {
  x = std::clamp(x, 0, image.width);
  y = std::clamp(y, 0, image.height);
  w = std::clamp(w, 0, image.width - x);
  h = std::clamp(h, 0, image.height - y);
  rt::Image8 out;
  out.width = w;
  out.height = h;
  out.rgb.resize(static_cast<size_t>(w) * h * 3);
  for (int r = 0; r < h; ++r)
    std::copy_n(&image.rgb[(static_cast<size_t>(y + r) * image.width + x) * 3], w * 3,
                &out.rgb[static_cast<size_t>(r) * w * 3]);
  return out;
}

rt::Image8 enlarge(const rt::Image8& image, int zoom) {
  zoom = std::max(1, zoom);
  rt::Image8 out;
  out.width = image.width * zoom;
  out.height = image.height * zoom;
  out.rgb.resize(static_cast<size_t>(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      std::copy_n(&image.rgb[(static_cast<size_t>(y / zoom) * image.width + x / zoom) * 3], 3,
                  &out.rgb[(static_cast<size_t>(y) * out.width + x) * 3]);
  return out;
}

std::string html_escape(const std::string& text) {
  // Numeric references serve text and attribute values alike; bytes of UTF-8 pass as they are.
  std::string out;
  for (char c : text)
    out += c && std::strchr("&<>\"'", c) ? "&#" + std::to_string(c) + ";" : std::string(1, c);
  return out;
}

}  // namespace cmp
