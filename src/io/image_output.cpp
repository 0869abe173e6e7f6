#include "io/image_output.h"

#include <OpenEXR/ImfChannelList.h>

#include <cctype>
#include <stdexcept>

#include <filesystem>

#include "io/exr_file.h"
#include "io/jpeg_io.h"
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

ImageFormat image_format_of(const std::string& path) {
  // The file name's last dot on: ".exr" alone is an EXR name too, as it always was.
  const std::string name = std::filesystem::path(path).filename().string();
  const size_t dot = name.rfind('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext.empty() || ext == ".png") return ImageFormat::kPng;
  if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::kJpeg;
  if (ext == ".exr") return ImageFormat::kExr;
  return ImageFormat::kUnknown;
}

bool is_exr_path(const std::string& path) { return image_format_of(path) == ImageFormat::kExr; }

std::string tonemap_path_for(const std::string& image) {
  return std::filesystem::path(image).replace_extension(".png").string();
}

void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 Quantize quantize) {
  switch (image_format_of(path)) {
    case ImageFormat::kExr:
      write_exr(path, width, height, rgb);
      return;
    case ImageFormat::kJpeg:
      write_jpeg(path, to_8bit(width, height, rgb, quantize));
      return;
    case ImageFormat::kPng:
      write_png(path, to_8bit(width, height, rgb, quantize));
      return;
    case ImageFormat::kUnknown:
      break;
  }
  throw std::runtime_error(path +
                           ": cannot write an image: the extension is not .png, .jpg, "
                           ".jpeg or .exr");
}

}  // namespace rt
