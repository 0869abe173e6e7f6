// Helpers of the PNG tests (tests/io/png_write_test.cpp, tests/io/png_read_test.cpp): a fixture
// with a temporary directory, byte-level file access, chunk-level PNG construction for inputs
// libpng itself would refuse to write, and libpng-written inputs of every color type.
#pragma once

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/png_io.h"
#include "support/test_scene.h"

namespace rt::test {

using Bytes = std::vector<uint8_t>;

// A fresh directory per test, removed afterwards (also after a test made it read-only).
class PngIoTest : public TempDirTest {
 protected:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ec);
    TempDirTest::TearDown();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

inline std::vector<std::string> entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

// Returns the message of the std::runtime_error thrown by f, or "" (and a failure) if none.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::runtime_error";
  return "";
}

inline Image8 pattern_image(int width, int height) {
  Image8 img;
  img.width = width;
  img.height = height;
  for (int i = 0; i < width * height * 3; ++i) {
    img.rgb.push_back(static_cast<uint8_t>(i * 37 + 11));
  }
  img.rgb[0] = 0;
  img.rgb[1] = 255;
  return img;
}

// --- Minimal chunk-level PNG construction, for inputs libpng itself would refuse to write. ---

inline uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0) {
  crc = ~crc;
  for (size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline void put_u32(Bytes* out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<uint8_t>(v >> shift));
}

inline void put_chunk(Bytes* out, const char* type, const Bytes& data) {
  put_u32(out, static_cast<uint32_t>(data.size()));
  Bytes body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out->insert(out->end(), body.begin(), body.end());
  put_u32(out, crc32(body.data(), body.size()));
}

inline Bytes signature() { return {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}; }

inline Bytes ihdr(uint32_t width, uint32_t height, uint8_t bit_depth, uint8_t color_type) {
  Bytes d;
  put_u32(&d, width);
  put_u32(&d, height);
  d.insert(d.end(), {bit_depth, color_type, 0, 0, 0});
  return d;
}

// Concatenated IDAT payloads of a well-formed file.
inline Bytes idat_payload(const Bytes& png) {
  Bytes data;
  for (size_t pos = 8; pos + 12 <= png.size();) {
    const uint32_t len = (uint32_t{png[pos]} << 24) | (uint32_t{png[pos + 1]} << 16) |
                         (uint32_t{png[pos + 2]} << 8) | png[pos + 3];
    if (std::string(png.begin() + pos + 4, png.begin() + pos + 8) == "IDAT") {
      data.insert(data.end(), png.begin() + pos + 8, png.begin() + pos + 8 + len);
    }
    pos += 12 + len;
  }
  return data;
}

// --- Writing test inputs of any color type with libpng directly. ---

struct RawPng {
  int width = 0, height = 0, bit_depth = 8, color_type = PNG_COLOR_TYPE_RGB;
  int interlace = PNG_INTERLACE_NONE;
  std::vector<Bytes> rows;         // Packed rows as stored in the file (16-bit big-endian).
  std::vector<png_color> palette;  // For PNG_COLOR_TYPE_PALETTE.
  Bytes trns;                      // Palette alpha values, if any.
};

inline RawPng raw_png(int width, int height, int bit_depth, int color_type,
                      int interlace = PNG_INTERLACE_NONE) {
  RawPng raw;
  raw.width = width;
  raw.height = height;
  raw.bit_depth = bit_depth;
  raw.color_type = color_type;
  raw.interlace = interlace;
  return raw;
}

inline void raw_png_body(png_structp png, png_infop info, std::FILE* file, const RawPng& raw,
                         png_bytep* rows) {
  png_init_io(png, file);
  png_set_IHDR(png, info, raw.width, raw.height, raw.bit_depth, raw.color_type, raw.interlace,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!raw.palette.empty()) {
    png_set_PLTE(png, info, raw.palette.data(), static_cast<int>(raw.palette.size()));
  }
  if (!raw.trns.empty()) {
    png_set_tRNS(png, info, raw.trns.data(), static_cast<int>(raw.trns.size()), nullptr);
  }
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
}

inline bool write_raw_png_impl(std::FILE* file, const RawPng* raw, png_bytep* rows) {
  // Default libpng error handler: prints the message and longjmps to the setjmp below.
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  raw_png_body(png, info, file, *raw, rows);
  png_destroy_write_struct(&png, &info);
  return true;
}

inline void write_raw_png(const std::string& path, const RawPng& raw) {
  std::vector<png_bytep> rows;
  for (const Bytes& row : raw.rows) rows.push_back(const_cast<png_bytep>(row.data()));
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  const bool ok = write_raw_png_impl(file, &raw, rows.data());
  std::fclose(file);
  ASSERT_TRUE(ok);
}

// Reads back a 2-pixel-per-row image written with `raw` and compares with expected RGB.
inline void expect_reads_as(const std::string& path, const RawPng& raw, const Bytes& expected) {
  write_raw_png(path, raw);
  const Image8 img = read_png(path);
  EXPECT_EQ(img.width, raw.width);
  EXPECT_EQ(img.height, raw.height);
  EXPECT_EQ(img.rgb, expected);
}

}  // namespace rt::test
