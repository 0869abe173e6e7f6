// `compare summary IMAGE`: what a file holds, before comparing it with anything: size,
// range, NaN and infinity counts and mean per channel, and the samples when moments exist.
#pragma once

#include <string>

namespace cmp {

// The summary of a PNG (with the moment file beside it, when there is one), an EXR or HDR
// image, or a moment file, as lines of text. Throws std::runtime_error naming the file.
std::string summarise(const std::string& path);

}  // namespace cmp
