#include "io/jpeg_io.h"

#include <stdexcept>

#include "image/jpeg_error.h"
#include "io/file_util.h"
#include "io/partial_mark.h"

namespace rt {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": cannot write JPEG: " + why);
}

// The encoded bytes, which libjpeg grows in place; beside the error state (whose address
// is libjpeg's), rather than in locals, so they are still known after a longjmp.
struct JpegWriteError : JpegError {
  unsigned char* out = nullptr;
  unsigned long size = 0;
};

}  // namespace

void write_jpeg(const std::string& path, const Image8& image, int quality) {
  if (image.width <= 0 || image.height <= 0 || image.width > 65500 || image.height > 65500 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    fail(path,
         "invalid image size " + std::to_string(image.width) + "x" + std::to_string(image.height));
  jpeg_compress_struct cinfo;
  JpegWriteError err;
  cinfo.err = jpeg_error_jump(&err);
  if (setjmp(err.jump)) {
    jpeg_destroy_compress(&cinfo);
    std::free(err.out);
    fail(path, err.message);
  }
  jpeg_create_compress(&cinfo);
  jpeg_mem_dest(&cinfo, &err.out, &err.size);
  cinfo.image_width = static_cast<JDIMENSION>(image.width);
  cinfo.image_height = static_cast<JDIMENSION>(image.height);
  cinfo.input_components = 3;
  cinfo.in_color_space = JCS_RGB;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, quality, TRUE);
  for (int c = 0; c < 3; ++c)
    cinfo.comp_info[c].h_samp_factor = cinfo.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&cinfo, TRUE);
  if (!image.samples_mark.empty()) {
    const std::string comment = std::string(kSamplesMarkKey) + "=" + image.samples_mark;
    jpeg_write_marker(&cinfo, JPEG_COM, reinterpret_cast<const JOCTET*>(comment.data()),
                      static_cast<unsigned>(comment.size()));
  }
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(image.rgb.data() +
                                        static_cast<size_t>(cinfo.next_scanline) * image.width * 3);
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  jpeg_destroy_compress(&cinfo);
  const int werr = write_file_atomic(path, err.out, err.size);
  std::free(err.out);
  if (werr) fail(path, errno_text(werr));
}

}  // namespace rt
