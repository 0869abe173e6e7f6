// The one image writer: the format follows the file name's extension. ".exr" (any case)
// writes linear radiance as 32-bit float RGB, unclamped (255 = the PNG's white), for HDR
// use; ".jpg" and ".jpeg" an 8-bit JPEG of quality 95 (io/jpeg_io.h); ".png" or no
// extension an 8-bit PNG. The 8-bit images are clamped and quantized as to_8bit does
// (truncated by default, the course's convention). All are written atomically
// (io/file_util.h). The loader refuses any other extension (image_format_of).
#pragma once

#include <string>
#include <vector>

#include "io/png_io.h"

namespace rt {

// `rgb`: 3 floats per pixel, row-major, top row first. Throws std::runtime_error
// ("<path>: cannot write PNG|EXR: <reason>") on failure, leaving no file behind.
// `samples_mark` non-empty: the image is partial and says so (io/partial_mark.h).
void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 Quantize quantize = Quantize::kTruncate, const std::string& samples_mark = "");

// True when `path` names an OpenEXR file (".exr", any case).
bool is_exr_path(const std::string& path);

enum class ImageFormat { kPng, kJpeg, kExr, kUnknown };

// The format write_image gives `path`, by its extension (any case): kUnknown for an
// extension it cannot write (".bmp", ".hdr").
ImageFormat image_format_of(const std::string& path);

// Where a camera with <Tonemap> whose image is the HDR `image` (an .exr) writes its
// tone-mapped 8-bit image: beside it, with the extension .png.
std::string tonemap_path_for(const std::string& image);

}  // namespace rt
