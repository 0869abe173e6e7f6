// Tests for PNG I/O: exact float -> 8-bit conversion, exact round trips, atomic writes that
// leave nothing behind on failure, every PNG color type on read, and corrupt input that must end
// in std::runtime_error rather than a crash.
#include "io/png_io.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rt {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;

// A fresh directory per test, removed afterwards.
class PngIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() /
           ("png_io_test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

// Returns the message of the std::runtime_error thrown by f, or "" (and a failure) if none.
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::runtime_error";
  return "";
}

Image8 pattern_image(int width, int height) {
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

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0) {
  crc = ~crc;
  for (size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void put_u32(Bytes* out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<uint8_t>(v >> shift));
}

void put_chunk(Bytes* out, const char* type, const Bytes& data) {
  put_u32(out, static_cast<uint32_t>(data.size()));
  Bytes body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out->insert(out->end(), body.begin(), body.end());
  put_u32(out, crc32(body.data(), body.size()));
}

Bytes signature() { return {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}; }

Bytes ihdr(uint32_t width, uint32_t height, uint8_t bit_depth, uint8_t color_type) {
  Bytes d;
  put_u32(&d, width);
  put_u32(&d, height);
  d.insert(d.end(), {bit_depth, color_type, 0, 0, 0});
  return d;
}

// Concatenated IDAT payloads of a well-formed file.
Bytes idat_payload(const Bytes& png) {
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

RawPng raw_png(int width, int height, int bit_depth, int color_type,
               int interlace = PNG_INTERLACE_NONE) {
  RawPng raw;
  raw.width = width;
  raw.height = height;
  raw.bit_depth = bit_depth;
  raw.color_type = color_type;
  raw.interlace = interlace;
  return raw;
}

void raw_png_body(png_structp png, png_infop info, std::FILE* file, const RawPng& raw,
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

bool write_raw_png_impl(std::FILE* file, const RawPng* raw, png_bytep* rows) {
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

void write_raw_png(const std::string& path, const RawPng& raw) {
  std::vector<png_bytep> rows;
  for (const Bytes& row : raw.rows) rows.push_back(const_cast<png_bytep>(row.data()));
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  const bool ok = write_raw_png_impl(file, &raw, rows.data());
  std::fclose(file);
  ASSERT_TRUE(ok);
}

// Reads back a 2-pixel-per-row image written with `raw` and compares with expected RGB.
void expect_reads_as(const std::string& path, const RawPng& raw, const Bytes& expected) {
  write_raw_png(path, raw);
  const Image8 img = read_png(path);
  EXPECT_EQ(img.width, raw.width);
  EXPECT_EQ(img.height, raw.height);
  EXPECT_EQ(img.rgb, expected);
}

// ---------------------------------------------------------------------------------------------

TEST(ToEightBit, RoundsHalfAwayFromZeroAndClamps) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> in = {254.5f, -3.0f, 300.0f, nan, 127.49f, 127.5f,
                                 0.5f,   0.49f, 255.0f, inf, -inf,    -0.0f};
  const Image8 img = to_8bit(4, 1, in, Quantize::kRound);
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.height, 1);
  EXPECT_EQ(img.rgb, (Bytes{255, 0, 255, 0, 127, 128, 1, 0, 255, 255, 0, 0}));
}

// The default, as the course's renderer: clamp, then drop the fraction.
TEST(ToEightBit, TruncatesByDefaultAfterClamping) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> in = {254.99f, -3.0f, 300.0f, nan, 127.49f, 127.5f,
                                 0.99f,   1.0f,  255.0f, inf, -inf,    -0.0f};
  EXPECT_EQ(to_8bit(4, 1, in).rgb, (Bytes{254, 0, 255, 0, 127, 127, 0, 1, 255, 255, 0, 0}));
  EXPECT_EQ(to_8bit(4, 1, in, Quantize::kTruncate).rgb, to_8bit(4, 1, in).rgb);
}

TEST(ToEightBit, RejectsWrongBufferSize) {
  EXPECT_THROW(to_8bit(2, 2, std::vector<float>(11)), std::invalid_argument);
  EXPECT_THROW(to_8bit(-1, 2, std::vector<float>(6)), std::invalid_argument);
  EXPECT_EQ(to_8bit(0, 0, {}).rgb.size(), 0u);
}

TEST_F(PngIoTest, RoundTripIsExactAndLeavesOnlyTheFile) {
  const Image8 img = pattern_image(7, 5);
  write_png(path("out.png"), img);
  const Image8 back = read_png(path("out.png"));
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
}

TEST_F(PngIoTest, ReplacesExistingFile) {
  write_bytes(path("out.png"), Bytes{'o', 'l', 'd'});
  const Image8 img = pattern_image(3, 2);
  write_png(path("out.png"), img);
  EXPECT_EQ(read_png(path("out.png")).rgb, img.rgb);
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
}

TEST_F(PngIoTest, MissingDirectoryThrowsAndLeavesNothing) {
  const std::string target = path("no_such_dir/out.png");
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_NE(msg.find(target + ": cannot write PNG: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(PngIoTest, UncreatableProcPathThrows) {
  // /proc refuses new files even for root, unlike a chmod'ed directory.
  const std::string target = "/proc/png_io_test_" + std::to_string(::getpid()) + ".png";
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_EQ(msg.rfind(target + ": cannot write PNG: ", 0), 0u) << msg;
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(PngIoTest, ReadOnlyDirectoryThrowsAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: directory permissions do not apply";
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string target = path("out.png");
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_NE(msg.find(target + ": cannot write PNG: Permission denied"), std::string::npos) << msg;
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(PngIoTest, RenameFailureRemovesTemporaryFile) {
  // The temporary file is written fine; only the final rename over a directory fails.
  fs::create_directory(path("out.png"));
  const std::string msg = error_of([&] { write_png(path("out.png"), pattern_image(2, 2)); });
  EXPECT_NE(msg.find(path("out.png") + ": cannot write PNG: "), std::string::npos) << msg;
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
  EXPECT_TRUE(fs::is_directory(path("out.png")));
}

TEST_F(PngIoTest, InconsistentImageThrowsWithoutWriting) {
  Image8 bad = pattern_image(2, 2);
  bad.rgb.pop_back();
  EXPECT_NE(error_of([&] { write_png(path("a.png"), bad); }).find("cannot write PNG"),
            std::string::npos);
  EXPECT_NE(error_of([&] { write_png(path("b.png"), Image8{}); }).find("cannot write PNG"),
            std::string::npos);
  EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(PngIoTest, ReadMissingFileThrows) {
  const std::string msg = error_of([&] { read_png(path("missing.png")); });
  EXPECT_EQ(msg, path("missing.png") + ": cannot read PNG: No such file or directory");
}

TEST_F(PngIoTest, ReadNonPngThrows) {
  write_bytes(path("text.png"), Bytes{'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd'});
  EXPECT_EQ(error_of([&] { read_png(path("text.png")); }),
            path("text.png") + ": cannot read PNG: not a PNG file");
  EXPECT_NE(error_of([&] { read_png(dir_.string()); }).find("cannot read PNG"), std::string::npos);
}

TEST_F(PngIoTest, EveryTruncationThrows) {
  write_png(path("full.png"), pattern_image(9, 7));
  const Bytes full = read_bytes(path("full.png"));
  ASSERT_GT(full.size(), 60u);
  for (size_t len = 0; len < full.size(); ++len) {
    write_bytes(path("cut.png"), Bytes(full.begin(), full.begin() + len));
    const std::string msg = error_of([&] { read_png(path("cut.png")); });
    EXPECT_EQ(msg.rfind(path("cut.png") + ": cannot read PNG: ", 0), 0u) << "len " << len;
  }
}

TEST_F(PngIoTest, FlippedBytesNeverCrash) {
  write_png(path("full.png"), pattern_image(6, 4));
  const Bytes full = read_bytes(path("full.png"));
  for (size_t i = 0; i < full.size(); ++i) {
    for (uint8_t mask : {0x01, 0x80, 0xFF}) {
      Bytes bytes = full;
      bytes[i] ^= mask;
      write_bytes(path("bad.png"), bytes);
      try {
        const Image8 img = read_png(path("bad.png"));
        EXPECT_EQ(img.rgb.size(), static_cast<size_t>(img.width) * img.height * 3);
      } catch (const std::runtime_error&) {
        // Expected for nearly every position: CRCs cover all chunk data.
      }
    }
  }
}

TEST_F(PngIoTest, CorruptCompressedDataWithValidCrcNeverCrashes) {
  // Fixing up the CRC gets the damage past libpng's chunk checks into zlib and the unfilter.
  write_png(path("full.png"), pattern_image(8, 8));
  const Bytes payload = idat_payload(read_bytes(path("full.png")));
  ASSERT_FALSE(payload.empty());
  std::mt19937 rng(12345);
  int failures = 0;
  for (int iter = 0; iter < 300; ++iter) {
    Bytes data = payload;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) data[rng() % data.size()] = static_cast<uint8_t>(rng());
    if (iter % 3 == 0) data.resize(rng() % data.size());
    Bytes png = signature();
    put_chunk(&png, "IHDR", ihdr(8, 8, 8, PNG_COLOR_TYPE_RGB));
    put_chunk(&png, "IDAT", data);
    put_chunk(&png, "IEND", {});
    write_bytes(path("bad.png"), png);
    try {
      const Image8 img = read_png(path("bad.png"));
      EXPECT_EQ(img.width, 8);
      EXPECT_EQ(img.rgb.size(), 8u * 8 * 3);
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path("bad.png") + ": cannot read PNG: ", 0), 0u);
      ++failures;
    }
  }
  EXPECT_GT(failures, 0);
}

TEST_F(PngIoTest, HugeDimensionsAreRefusedBeforeAllocating) {
  Bytes png = signature();
  put_chunk(&png, "IHDR", ihdr(60000, 60000, 8, PNG_COLOR_TYPE_RGB));
  put_chunk(&png, "IDAT", Bytes{0x78, 0x9C, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
  put_chunk(&png, "IEND", {});
  write_bytes(path("huge.png"), png);
  EXPECT_EQ(error_of([&] { read_png(path("huge.png")); }),
            path("huge.png") + ": cannot read PNG: image too large");
}

TEST_F(PngIoTest, ReadsGray8) {
  RawPng raw = raw_png(2, 2, 8, PNG_COLOR_TYPE_GRAY);
  raw.rows = {{0, 200}, {17, 255}};
  expect_reads_as(path("g8.png"), raw, {0, 0, 0, 200, 200, 200, 17, 17, 17, 255, 255, 255});
}

TEST_F(PngIoTest, ReadsGray16) {
  RawPng raw = raw_png(2, 1, 16, PNG_COLOR_TYPE_GRAY);
  raw.rows = {{0x12, 0x12, 0xFF, 0xFF}};  // 0x1212 = 0x12 * 257 scales to exactly 0x12.
  expect_reads_as(path("g16.png"), raw, {0x12, 0x12, 0x12, 255, 255, 255});
}

TEST_F(PngIoTest, ReadsLowBitDepthGray) {
  RawPng one = raw_png(3, 1, 1, PNG_COLOR_TYPE_GRAY);
  one.rows = {{0b10100000}};
  expect_reads_as(path("g1.png"), one, {255, 255, 255, 0, 0, 0, 255, 255, 255});
  RawPng two = raw_png(4, 1, 2, PNG_COLOR_TYPE_GRAY);
  two.rows = {{0b00011011}};
  expect_reads_as(path("g2.png"), two, {0, 0, 0, 85, 85, 85, 170, 170, 170, 255, 255, 255});
}

TEST_F(PngIoTest, ReadsGrayAlphaDroppingAlpha) {
  RawPng raw = raw_png(2, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA);
  raw.rows = {{100, 0, 50, 128}};
  expect_reads_as(path("ga.png"), raw, {100, 100, 100, 50, 50, 50});
}

TEST_F(PngIoTest, ReadsRgbaDroppingAlphaWithoutPremultiplying) {
  RawPng raw = raw_png(2, 1, 8, PNG_COLOR_TYPE_RGBA);
  raw.rows = {{10, 20, 30, 0, 200, 150, 100, 128}};
  expect_reads_as(path("rgba.png"), raw, {10, 20, 30, 200, 150, 100});
}

TEST_F(PngIoTest, ReadsRgb16AndRgba16) {
  RawPng rgb = raw_png(1, 1, 16, PNG_COLOR_TYPE_RGB);
  rgb.rows = {{0x01, 0x01, 0x80, 0x80, 0xFF, 0xFF}};
  expect_reads_as(path("rgb16.png"), rgb, {0x01, 0x80, 0xFF});
  RawPng rgba = raw_png(1, 1, 16, PNG_COLOR_TYPE_RGBA);
  rgba.rows = {{0x40, 0x40, 0x00, 0x00, 0xFE, 0xFE, 0x12, 0x34}};
  expect_reads_as(path("rgba16.png"), rgba, {0x40, 0x00, 0xFE});
}

TEST_F(PngIoTest, ReadsPaletteWithTransparency) {
  RawPng raw = raw_png(3, 1, 8, PNG_COLOR_TYPE_PALETTE);
  raw.palette = {{255, 0, 0}, {0, 128, 255}, {7, 8, 9}};
  raw.trns = {0, 128};  // Makes libpng's palette expansion add alpha, which must be dropped.
  raw.rows = {{2, 0, 1}};
  expect_reads_as(path("pal.png"), raw, {7, 8, 9, 255, 0, 0, 0, 128, 255});
}

TEST_F(PngIoTest, ReadsPalette4Bit) {
  RawPng raw = raw_png(3, 1, 4, PNG_COLOR_TYPE_PALETTE);
  raw.palette = {{1, 2, 3}, {4, 5, 6}};
  raw.rows = {{0x10, 0x10}};
  expect_reads_as(path("pal4.png"), raw, {4, 5, 6, 1, 2, 3, 4, 5, 6});
}

TEST_F(PngIoTest, ReadsInterlacedRgb) {
  const Image8 img = pattern_image(5, 6);
  RawPng raw = raw_png(5, 6, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7);
  for (int y = 0; y < 6; ++y) {
    raw.rows.emplace_back(img.rgb.begin() + y * 15, img.rgb.begin() + (y + 1) * 15);
  }
  expect_reads_as(path("adam7.png"), raw, img.rgb);
}

}  // namespace
}  // namespace rt
