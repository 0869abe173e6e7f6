// Reading PNG files: every PNG color type, bit depth and interlacing, and corrupt or
// truncated input that must end in std::runtime_error rather than a crash.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>

#include "io/png_io.h"
#include "support/png_builder.h"

namespace rt {
namespace {

using namespace test;
namespace fs = std::filesystem;

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
