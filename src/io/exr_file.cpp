#include "io/exr_file.h"

#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>

#include <stdexcept>

#include "io/file_util.h"

namespace rt {

void write_exr_atomic(const std::string& path, const Imf::Header& header,
                      const Imf::FrameBuffer& frame_buffer, int height) {
  Imf::StdOSStream stream;
  {
    Imf::OutputFile out(stream, header);
    out.setFrameBuffer(frame_buffer);
    out.writePixels(height);
  }  // The offset table is written when the file closes: take the bytes after it.
  const std::string bytes = stream.str();
  if (const int err = write_file_atomic(path, bytes.data(), bytes.size()))
    throw std::runtime_error(errno_text(err));
}

}  // namespace rt
