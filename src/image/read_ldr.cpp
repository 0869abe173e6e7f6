#include "image/read_ldr.h"

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "image/jpeg_error.h"
#include "io/png_io.h"

namespace rt {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": cannot read image: " + why);
}

// Level -1 is a warning: damaged data (a truncated file, a corrupt segment) that libjpeg
// would decode with the missing part grey. A texture so damaged gives a silently wrong
// image, so the warning is an error too. Levels 0 and up are trace messages.
void on_jpeg_message(j_common_ptr cinfo, int level) {
  if (level < 0) (*cinfo->err->error_exit)(cinfo);
}

ImageF read_jpeg(const std::string& path, std::FILE* file) {
  jpeg_decompress_struct cinfo;
  JpegError err;
  cinfo.err = jpeg_error_jump(&err);
  err.mgr.emit_message = on_jpeg_message;
  // Declared before setjmp so a longjmp leaves it in a defined state.
  ImageF* volatile out = new ImageF;
  std::unique_ptr<ImageF> guard(out);
  if (setjmp(err.jump)) {
    jpeg_destroy_decompress(&cinfo);
    fail(path, std::string("JPEG: ") + err.message);
  }
  jpeg_create_decompress(&cinfo);
  jpeg_stdio_src(&cinfo, file);
  jpeg_read_header(&cinfo, TRUE);
  cinfo.out_color_space = JCS_RGB;  // Grey and YCbCr files both come out as RGB.
  jpeg_start_decompress(&cinfo);
  if (static_cast<double>(cinfo.output_width) * cinfo.output_height > (1 << 28)) {
    jpeg_destroy_decompress(&cinfo);
    fail(path, "image too large");
  }
  out->width = static_cast<int>(cinfo.output_width);
  out->height = static_cast<int>(cinfo.output_height);
  out->channels = 3;
  out->pixels.resize(out->size() * 3);
  std::vector<unsigned char> row(static_cast<size_t>(out->width) * 3);
  while (cinfo.output_scanline < cinfo.output_height) {
    size_t y = cinfo.output_scanline;
    JSAMPROW rows[1] = {row.data()};
    jpeg_read_scanlines(&cinfo, rows, 1);
    for (size_t i = 0; i < row.size(); ++i) out->pixels[y * row.size() + i] = row[i];
  }
  jpeg_finish_decompress(&cinfo);
  jpeg_destroy_decompress(&cinfo);
  return std::move(*guard);
}

}  // namespace

ImageF read_ldr(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) fail(path, std::strerror(errno));
  unsigned char magic[8] = {};
  size_t got = std::fread(magic, 1, sizeof magic, file.get());
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got == 8 && std::memcmp(magic, kPng, 8) == 0) {
    Image8 img = read_png(path);  // Its errors already name the file in one line.
    ImageF out;
    out.width = img.width;
    out.height = img.height;
    out.channels = 3;
    out.pixels.assign(img.rgb.begin(), img.rgb.end());
    return out;
  }
  if (got >= 3 && magic[0] == 0xff && magic[1] == 0xd8 && magic[2] == 0xff) {
    std::rewind(file.get());
    return read_jpeg(path, file.get());
  }
  fail(path, got == 0 ? "empty file" : "neither PNG nor JPEG");
}

}  // namespace rt
