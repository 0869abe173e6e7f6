// The JPEG writer (libjpeg-turbo, the library the texture reader uses): an ImageName
// ending in .jpg or .jpeg gets a JPEG, not PNG bytes under a JPEG name.
#pragma once

#include <string>

#include "io/png_io.h"

namespace rt {

// The quality of every JPEG the renderer writes: high enough that the 8-bit image's
// levels survive to within a few (4:4:4, no chroma subsampling), as a user viewing the
// image expects; use .png for exact levels.
constexpr int kJpegQuality = 95;

// Encodes in memory, then writes atomically (io/file_util.h). Throws std::runtime_error
// "<path>: cannot write JPEG: <reason>", leaving no file behind.
void write_jpeg(const std::string& path, const Image8& image, int quality = kJpegQuality);

}  // namespace rt
