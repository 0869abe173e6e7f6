#include "image/read_hdr.h"
#include "image/read_ldr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "util/errors.h"

namespace rt {
namespace {

InputError exr_error(const std::string& path, const std::string& why) {
  return InputError(path + ": cannot read EXR: " + why);
}

InputError hdr_error(const std::string& path, const std::string& why) {
  return InputError(path + ": cannot read HDR: " + why);
}

// The largest image either reader accepts (2^28 pixels): a corrupt header must not make
// us allocate tens of gigabytes.
constexpr long long kMaxPixels = 1LL << 28;
// The widest EXR accepted (environment maps are at most 16K wide).
constexpr long long kMaxExrWidth = 1LL << 16;

// OpenEXR 3.1 allocates and clears each header attribute at the size the file claims
// before reading it: a 426-byte file claiming a 200 MB attribute took 25 s under ASan. The
// first header's attribute sizes (name, type, 4-byte size, value; an empty name ends it)
// must fit in the file, else it is refused here.
void check_exr_attribute_sizes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> d((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
  size_t p = 8;  // Magic number and version.
  auto text = [&](std::string* out) {
    out->clear();
    while (p < d.size() && d[p] != 0) out->push_back(static_cast<char>(d[p++]));
    return p++ < d.size();
  };
  std::string name, type;
  while (p < d.size() && text(&name) && !name.empty() && text(&type) && p + 4 <= d.size()) {
    const uint32_t size = d[p] | d[p + 1] << 8 | d[p + 2] << 16 | uint32_t{d[p + 3]} << 24;
    p += 4;
    if (size > d.size() - p)
      throw exr_error(path, "header attribute '" + name + "' claims " + std::to_string(size) +
                                " bytes, the file has " + std::to_string(d.size() - p) + " left");
    // OpenEXR sizes its line buffers from the data window before reading a pixel: a wide
    // window in a small file would take gigabytes there, so it is checked here first.
    if (name == "dataWindow" && type == "box2i" && size == 16) {
      auto at = [&](size_t k) {
        return static_cast<int32_t>(d[p + k] | d[p + k + 1] << 8 | d[p + k + 2] << 16 |
                                    uint32_t{d[p + k + 3]} << 24);
      };
      const long long w = static_cast<long long>(at(8)) - at(0) + 1;
      const long long h = static_cast<long long>(at(12)) - at(4) + 1;
      if (w <= 0 || h <= 0 || w > kMaxExrWidth || w * h > kMaxPixels)
        throw exr_error(path, "data window of " + std::to_string(w) + "x" + std::to_string(h));
    }
    p += size;
  }
}

}  // namespace

ImageF read_exr(const std::string& path) {
  ImageF img;
  img.max_value = 0.0f;
  check_exr_attribute_sizes(path);
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
    long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
    if (w <= 0 || h <= 0 || w * h > kMaxPixels)
      throw exr_error(path, "data window of " + std::to_string(w) + "x" + std::to_string(h));
    const Imf::ChannelList& ch = file.header().channels();
    std::vector<const char*> names;
    if (ch.findChannel("R") && ch.findChannel("G") && ch.findChannel("B")) {
      names = {"R", "G", "B"};
      if (ch.findChannel("A")) names.push_back("A");
    } else if (ch.findChannel("Y")) {
      names = {"Y"};
    } else {
      throw exr_error(path, "no R, G, B or Y channels");
    }
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    img.channels = static_cast<int>(names.size());
    // Read in strips of 64 rows, the pixels growing with each: a damaged file whose header
    // claims 16384x16384 fails at its first missing strip instead of allocating 4 GiB.
    // OpenEXR addresses pixel (x, y) as base + x * xstride + y * ystride over the data
    // window, which need not start at (0, 0); the base moves as the buffer grows.
    const size_t xs = sizeof(float) * img.channels, ys = xs * img.width;
    for (long long row = 0; row < h; row += 64) {
      const int y0 = static_cast<int>(dw.min.y + row);
      const int y1 = static_cast<int>(dw.min.y + std::min(h - 1, row + 63));
      img.pixels.resize(static_cast<size_t>(y1 - dw.min.y + 1) * img.width * img.channels);
      Imf::FrameBuffer fb;
      for (int c = 0; c < img.channels; ++c) {
        char* base = reinterpret_cast<char*>(img.pixels.data() + c) -
                     static_cast<ptrdiff_t>(dw.min.x) * xs - static_cast<ptrdiff_t>(dw.min.y) * ys;
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, base, xs, ys));
      }
      file.setFrameBuffer(fb);
      file.readPixels(y0, y1);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw exr_error(path, e.what());
  }
  return img;
}

namespace {

// Reads one header line (without its newline) from a byte buffer.
bool next_line(const std::vector<unsigned char>& d, size_t* pos, std::string* line) {
  line->clear();
  while (*pos < d.size() && d[*pos] != '\n') line->push_back(static_cast<char>(d[(*pos)++]));
  if (*pos >= d.size()) return false;
  ++*pos;
  return true;
}

// Decodes one scanline of `width` RGBE pixels at d[*pos], in either the flat layout or the
// run-length encoding of Radiance 2.0 (a 2, 2, width marker, then each of the four
// components as runs), into `out` (width * 4 bytes).
bool read_scanline(const std::vector<unsigned char>& d, size_t* pos, int width,
                   unsigned char* out) {
  size_t p = *pos;
  bool rle = width >= 8 && width < 32768 && p + 4 <= d.size() && d[p] == 2 && d[p + 1] == 2 &&
             ((d[p + 2] << 8) | d[p + 3]) == width && (d[p + 2] & 0x80) == 0;
  if (!rle) {
    if (p + static_cast<size_t>(width) * 4 > d.size()) return false;
    std::copy(d.begin() + p, d.begin() + p + width * 4, out);
    *pos = p + static_cast<size_t>(width) * 4;
    return true;
  }
  p += 4;
  for (int c = 0; c < 4; ++c) {
    int x = 0;
    while (x < width) {
      if (p >= d.size()) return false;
      int count = d[p++];
      bool run = count > 128;
      if (run) count -= 128;
      if (count == 0 || x + count > width) return false;
      if (run) {
        if (p >= d.size()) return false;
        for (int i = 0; i < count; ++i) out[(x + i) * 4 + c] = d[p];
        ++p;
      } else {
        if (p + count > d.size()) return false;
        for (int i = 0; i < count; ++i) out[(x + i) * 4 + c] = d[p + i];
        p += count;
      }
      x += count;
    }
  }
  *pos = p;
  return true;
}

}  // namespace

ImageF read_radiance_hdr(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw hdr_error(path, "cannot open the file");
  std::vector<unsigned char> d((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
  size_t pos = 0;
  std::string line;
  if (!next_line(d, &pos, &line) || line.rfind("#?", 0) != 0)
    throw hdr_error(path, "no '#?RADIANCE' signature");
  // Header variables until an empty line; only the pixel format matters here.
  for (;;) {
    if (!next_line(d, &pos, &line)) throw hdr_error(path, "header has no end");
    if (line.empty()) break;
    if (line.rfind("FORMAT=", 0) == 0 && line != "FORMAT=32-bit_rle_rgbe")
      throw hdr_error(path, "unsupported " + line);
  }
  if (!next_line(d, &pos, &line)) throw hdr_error(path, "no resolution line");
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(line.c_str(), "-Y %d +X %d%c", &h, &w, &tail) != 2)
    throw hdr_error(path, "unsupported resolution line '" + line + "' (only -Y h +X w)");
  if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > kMaxPixels)
    throw hdr_error(path, "image size " + std::to_string(w) + "x" + std::to_string(h));
  // The smallest scanline either layout can encode: flat, or (8 <= w < 32768) the 4-byte
  // marker plus one 2-byte run per 127 pixels of each component. A file too short for that
  // is refused before its pixels are allocated (3 GiB for an 80-byte file otherwise).
  long long min_line = 4LL * w;
  if (w >= 8 && w < 32768) min_line = std::min(min_line, 4 + 8 * ((w + 126) / 127LL));
  if (static_cast<long long>(d.size() - pos) < min_line * h)
    throw hdr_error(path, "pixel data of " + std::to_string(d.size() - pos) +
                              " bytes is too short for " + std::to_string(w) + "x" +
                              std::to_string(h) + " pixels");
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = 3;
  img.max_value = 0.0f;
  img.pixels.resize(img.size() * 3);
  std::vector<unsigned char> row(static_cast<size_t>(w) * 4);
  for (int y = 0; y < h; ++y) {
    if (!read_scanline(d, &pos, w, row.data()))
      throw hdr_error(path, "scanline " + std::to_string(y) + " is truncated or corrupt");
    for (int x = 0; x < w; ++x) {
      const unsigned char* rgbe = &row[static_cast<size_t>(x) * 4];
      float* o = &img.pixels[(static_cast<size_t>(y) * w + x) * 3];
      // Radiance's own decoding: the mantissa's bucket centre times 2^(e - 136).
      float f = rgbe[3] == 0 ? 0.0f : std::ldexp(1.0f, rgbe[3] - (128 + 8));
      for (int c = 0; c < 3; ++c) o[c] = rgbe[3] == 0 ? 0.0f : (rgbe[c] + 0.5f) * f;
    }
  }
  return img;
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = path.substr(
      path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

ImageF read_hdr_image(const std::string& path) {
  std::string ext = lower_extension(path);
  if (ext == ".exr") return read_exr(path);
  if (ext == ".hdr" || ext == ".pic") return read_radiance_hdr(path);
  throw InputError(path + ": not an HDR image (expected .exr, .hdr or .pic)");
}

bool has_hdr_extension(const std::string& path) {
  std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".pic";
}

ImageF read_any_image(const std::string& path) {
  return has_hdr_extension(path) ? read_hdr_image(path) : read_ldr(path);
}

std::string first_invalid_texel(const ImageF& img) {
  for (size_t i = 0; i < img.pixels.size(); ++i)
    if (!(img.pixels[i] >= 0 && std::isfinite(img.pixels[i]))) {
      size_t pixel = i / img.channels;
      char value[32];
      std::snprintf(value, sizeof value, "%.10g", img.pixels[i]);
      return "texel (" + std::to_string(pixel % img.width) + ", " +
             std::to_string(pixel / img.width) + ") is " + value;
    }
  return "";
}

}  // namespace rt
