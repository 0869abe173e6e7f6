// The one image writer: the format follows the file name's extension. ".exr" (any case)
// writes linear radiance as 32-bit float RGB, unclamped (255 = the PNG's white), for HDR
// use; any other name gets an 8-bit PNG, clamped and quantized as to_8bit does
// (truncated by default, the course's convention). Both are written atomically (io/file_util.h).
#pragma once

#include <string>
#include <vector>

#include "io/png_io.h"

namespace rt {

// `rgb`: 3 floats per pixel, row-major, top row first. Throws std::runtime_error
// ("<path>: cannot write PNG|EXR: <reason>") on failure, leaving no file behind.
void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 Quantize quantize = Quantize::kTruncate);

// True when `path` names an OpenEXR file (".exr", any case).
bool is_exr_path(const std::string& path);

}  // namespace rt
