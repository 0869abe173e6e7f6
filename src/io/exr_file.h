// Writing an OpenEXR file through io/file_util.h: the file is encoded in memory, then
// written atomically, so an EXR output is never seen half-written and no temporary remains.
#pragma once

#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>

#include <string>

namespace rt {

// Encodes `height` scanlines of `frame_buffer` under `header` and writes them to `path`.
// Throws std::runtime_error("<reason>") (no path: callers add their own prefix).
void write_exr_atomic(const std::string& path, const Imf::Header& header,
                      const Imf::FrameBuffer& frame_buffer, int height);

}  // namespace rt
