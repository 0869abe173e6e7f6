#include "io/image_output.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cctype>
#include <stdexcept>

#include <filesystem>

#include "io/exr_file.h"
#include "io/jpeg_io.h"
#include "io/partial_mark.h"
#include "io/png_io.h"

namespace rt {
namespace {

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb,
               const std::string& samples_mark) {
  try {
    if (width <= 0 || height <= 0 || rgb.size() != static_cast<size_t>(width) * height * 3)
      throw std::runtime_error("inconsistent image");
    Imf::Header h(width, height);
    h.compression() = Imf::ZIP_COMPRESSION;
    if (!samples_mark.empty()) h.insert(kSamplesMarkKey, Imf::StringAttribute(samples_mark));
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
                 Quantize quantize, const std::string& samples_mark) {
  const ImageFormat format = image_format_of(path);
  if (format == ImageFormat::kUnknown)
    throw std::runtime_error(path +
                             ": cannot write an image: the extension is not .png, .jpg, "
                             ".jpeg or .exr");
  if (format == ImageFormat::kExr) return write_exr(path, width, height, rgb, samples_mark);
  Image8 image8 = to_8bit(width, height, rgb, quantize);
  image8.samples_mark = samples_mark;
  if (format == ImageFormat::kJpeg) return write_jpeg(path, image8);
  write_png(path, image8);
}

}  // namespace rt
