// Reads the low-dynamic-range files textures come in (PNG through libpng, JPEG through
// libjpeg-turbo) into the shared ImageF, values on the file's own 0..255 scale.
#pragma once

#include <string>

#include "image/image.h"

namespace rt {

// Decodes `path` by its content (the first bytes), not its name: 8-bit RGB, grey
// replicated to RGB, alpha dropped. Throws std::runtime_error with one line
// "<path>: cannot read image: <reason>" for a missing, unreadable or corrupt file, or a
// format other than PNG and JPEG.
ImageF read_ldr(const std::string& path);

}  // namespace rt
