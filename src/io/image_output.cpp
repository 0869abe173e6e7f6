#include "io/image_output.h"

#include <OpenEXR/ImfChannelList.h>

#include <cctype>
#include <stdexcept>

#include "io/exr_file.h"
#include "io/png_io.h"

namespace rt {
namespace {

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  try {
    if (width <= 0 || height <= 0 || rgb.size() != static_cast<size_t>(width) * height * 3)
      throw std::runtime_error("inconsistent image");
    Imf::Header h(width, height);
    h.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    const char* const names[3] = {"R", "G", "B"};
    const size_t xs = 3 * sizeof(float), ys = xs * width;
    for (int c = 0; c < 3; ++c) {
      h.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      fb.insert(
          names[c],
          Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(rgb.data() + c)),
                     xs, ys));
    }
    write_exr_atomic(path, h, fb, height);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot write EXR: " + e.what());
  }
}

}  // namespace

bool is_exr_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr";
}

void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 Quantize quantize) {
  if (is_exr_path(path))
    write_exr(path, width, height, rgb);
  else
    write_png(path, to_8bit(width, height, rgb, quantize));
}

}  // namespace rt
