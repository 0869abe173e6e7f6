// PNG reading and writing with libpng.
//
// libpng reports errors by calling an error function that must not return; the only safe way
// out is longjmp back to a setjmp point. Throwing a C++ exception through libpng's C frames is
// undefined, so errors are recorded in a caller-owned PngErrorContext and longjmp'd. To keep
// setjmp/longjmp well defined in C++, the function that calls setjmp holds nothing but pointers
// set before the setjmp, and all the real work (with its locals) happens in a helper that has no
// object with a destructor alive when libpng may jump out of it.
#include "io/png_io.h"
#include "io/partial_mark.h"

#include <png.h>

#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/file_util.h"

namespace rt {
namespace {

// Larger reads are refused before allocation, so a hostile IHDR cannot demand gigabytes.
constexpr uint64_t kMaxReadBytes = uint64_t{1} << 30;

struct PngErrorContext {
  char message[256] = "unknown libpng error";
};

[[noreturn]] void fail_write(const std::string& path, const std::string& reason) {
  throw std::runtime_error(path + ": cannot write PNG: " + reason);
}

[[noreturn]] void fail_read(const std::string& path, const std::string& reason) {
  throw std::runtime_error(path + ": cannot read PNG: " + reason);
}

void on_png_error(png_structp png, png_const_charp message) {
  auto* ctx = static_cast<PngErrorContext*>(png_get_error_ptr(png));
  if (ctx != nullptr) {
    std::snprintf(ctx->message, sizeof ctx->message, "%s",
                  message != nullptr ? message : "unknown libpng error");
  }
  png_longjmp(png, 1);
}

// Warnings (e.g. a bad ancillary chunk) do not make the image unusable; stay quiet.
void on_png_warning(png_structp, png_const_charp) {}

// ---------------------------------------------------------------------------------------------
// Writing

void append_to_vector(png_structp png, png_bytep data, size_t length) {
  auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
  bool failed = false;
  try {
    out->insert(out->end(), data, data + length);
  } catch (...) {
    failed = true;
  }
  // Outside the try block: nothing with a destructor may be live when png_error longjmps.
  if (failed) png_error(png, "out of memory");
}

void flush_nothing(png_structp) {}

void encode_body(png_structp png, png_infop info, const Image8& image, std::vector<uint8_t>* out) {
  png_set_write_fn(png, out, append_to_vector, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_text text{};
  if (!image.samples_mark.empty()) {
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = const_cast<char*>(kSamplesMarkKey);
    text.text = const_cast<char*>(image.samples_mark.c_str());
    text.text_length = image.samples_mark.size();
    png_set_text(png, info, &text, 1);
  }
  png_write_info(png, info);
  const size_t stride = static_cast<size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.rgb.data() + y * stride);
  png_write_end(png, nullptr);
}

// Encodes into memory so that libpng errors never leave a half-written file behind and the
// file system part of write_png sees plain write(2) errors with a real errno.
bool encode_png(const Image8* image, std::vector<uint8_t>* out, PngErrorContext* ctx) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::snprintf(ctx->message, sizeof ctx->message, "cannot create libpng write struct");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(ctx->message, sizeof ctx->message, "cannot create libpng info struct");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  encode_body(png, info, *image, out);
  png_destroy_write_struct(&png, &info);
  return true;
}

// ---------------------------------------------------------------------------------------------
// Reading

void read_from_file(png_structp png, png_bytep data, size_t length) {
  auto* file = static_cast<std::FILE*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, file) != length) {
    png_error(png, std::ferror(file) ? "read error" : "unexpected end of file");
  }
}

void decode_body(png_structp png, png_infop info, std::FILE* file, Image8* out) {
  png_set_read_fn(png, file, read_from_file);
  png_set_sig_bytes(png, 8);  // read_png has consumed and checked the signature.
  png_read_info(png, info);

  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  const int color_type = png_get_color_type(png, info);
  if (uint64_t{width} * height * 3 > kMaxReadBytes) png_error(png, "image too large");
  // Deflate expands at most 1032:1, so the rows (a filter byte each) must fit in 1032 times
  // the file's size: a 69-byte file claiming 18000x18000 is refused here, before 1 GB of
  // pixels is allocated and cleared.
  const long at = std::ftell(file);
  std::fseek(file, 0, SEEK_END);
  const long file_size = std::ftell(file);
  std::fseek(file, at, SEEK_SET);
  if (file_size >= 0 &&
      uint64_t{height} * (png_get_rowbytes(png, info) + 1) > 1032 * uint64_t(file_size) + 1032)
    png_error(png, "file too short for the image size in its header");

  // Bring every layout to 8-bit RGB. No png_set_gamma: stored values are returned as is.
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
#ifdef PNG_READ_SCALE_16_TO_8_SUPPORTED
  if (bit_depth == 16) png_set_scale_16(png);  // Rounds, unlike strip_16 which truncates.
#else
  if (bit_depth == 16) png_set_strip_16(png);
#endif
  // Also covers the alpha that palette expansion adds when there is a tRNS chunk.
  png_set_strip_alpha(png);
  if ((color_type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(png);
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);

  const size_t stride = static_cast<size_t>(width) * 3;
  if (png_get_channels(png, info) != 3 || png_get_bit_depth(png, info) != 8 ||
      png_get_rowbytes(png, info) != stride) {
    png_error(png, "unsupported pixel layout after conversion");
  }

  out->width = static_cast<int>(width);
  out->height = static_cast<int>(height);
  bool alloc_failed = false;
  try {
    out->rgb.assign(stride * height, 0);
  } catch (...) {
    alloc_failed = true;
  }
  if (alloc_failed) png_error(png, "out of memory");

  // Interlaced images are read once per pass; libpng merges each pass into the row.
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < height; ++y) {
      png_read_row(png, out->rgb.data() + y * stride, nullptr);
    }
  }
  png_read_end(png, nullptr);  // Verifies the rest of the stream, so truncation is caught.
}

bool decode_png(std::FILE* file, Image8* out, PngErrorContext* ctx) {
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, ctx, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::snprintf(ctx->message, sizeof ctx->message, "cannot create libpng read struct");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    std::snprintf(ctx->message, sizeof ctx->message, "cannot create libpng info struct");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  decode_body(png, info, file, out);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

uint8_t float_to_byte(float v, Quantize quantize) {
  if (!(v > 0.0f)) return 0;  // Negative, zero and NaN.
  if (v >= 255.0f) return 255;
  // The conversion to an integer truncates toward zero, as the course's renderer does.
  return static_cast<uint8_t>(quantize == Quantize::kRound ? std::lround(v) : static_cast<long>(v));
}

}  // namespace

Image8 to_8bit(int width, int height, const std::vector<float>& rgb, Quantize quantize) {
  if (width < 0 || height < 0 ||
      rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) {
    throw std::invalid_argument("to_8bit: " + std::to_string(width) + "x" + std::to_string(height) +
                                " image needs " + "width*height*3 floats, got " +
                                std::to_string(rgb.size()));
  }
  Image8 image;
  image.width = width;
  image.height = height;
  image.rgb.resize(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) image.rgb[i] = float_to_byte(rgb[i], quantize);
  return image;
}

void write_png(const std::string& path, const Image8& image) {
  if (image.width <= 0 || image.height <= 0) {
    fail_write(path, "invalid image size " + std::to_string(image.width) + "x" +
                         std::to_string(image.height));
  }
  const size_t expected = static_cast<size_t>(image.width) * image.height * 3;
  if (image.rgb.size() != expected) {
    fail_write(path, "pixel buffer holds " + std::to_string(image.rgb.size()) +
                         " bytes, expected " + std::to_string(expected));
  }

  std::vector<uint8_t> encoded;
  PngErrorContext ctx;
  if (!encode_png(&image, &encoded, &ctx)) fail_write(path, ctx.message);

  if (const int err = write_file_atomic(path, encoded.data(), encoded.size()))
    fail_write(path, errno_text(err));
}

Image8 read_png(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) fail_read(path, errno_text(errno));

  png_byte signature[8];
  const size_t got = std::fread(signature, 1, sizeof signature, file);
  if (got != sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0) {
    const int err = std::ferror(file) ? errno : 0;
    std::fclose(file);
    fail_read(path, err != 0 ? errno_text(err) : "not a PNG file");
  }

  Image8 image;
  PngErrorContext ctx;
  const bool ok = decode_png(file, &image, &ctx);
  std::fclose(file);
  if (!ok) fail_read(path, ctx.message);
  return image;
}

}  // namespace rt
