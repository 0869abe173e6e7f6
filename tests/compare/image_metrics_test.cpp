// Tests for the image comparison metrics on small hand-made images with known answers.
#include "compare/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rt {
namespace {

Image8 make(int width, int height, std::vector<uint8_t> rgb) {
  Image8 img;
  img.width = width;
  img.height = height;
  img.rgb = std::move(rgb);
  return img;
}

// 2x2 pair with per-pixel differences (0,0,0), (10,0,0), (3,4,5), (255,0,0).
Image8 black2x2() { return make(2, 2, std::vector<uint8_t>(12, 0)); }
Image8 other2x2() { return make(2, 2, {0, 0, 0, 10, 0, 0, 3, 4, 5, 255, 0, 0}); }

TEST(DiffImages, KnownDifferences) {
  const ImageDiff d = diff_images(black2x2(), other2x2());
  const double mae = (10 + 3 + 4 + 5 + 255) / 12.0;
  const double rmse = std::sqrt((100 + 9 + 16 + 25 + 255 * 255) / 12.0);
  EXPECT_DOUBLE_EQ(d.mae, mae);
  EXPECT_DOUBLE_EQ(d.rmse, rmse);
  EXPECT_DOUBLE_EQ(d.psnr, 20 * std::log10(255 / rmse));
  EXPECT_EQ(d.max_abs, 255);
  EXPECT_DOUBLE_EQ(d.frac_over, 0.5);  // Max channel differences 0, 10, 5, 255 vs threshold 8.
  EXPECT_DOUBLE_EQ(d.frac_identical, 0.25);
}

TEST(DiffImages, ThresholdIsStrictAndOrderDoesNotMatter) {
  EXPECT_DOUBLE_EQ(diff_images(black2x2(), other2x2(), 10).frac_over, 0.25);
  EXPECT_DOUBLE_EQ(diff_images(black2x2(), other2x2(), 4).frac_over, 0.75);
  EXPECT_DOUBLE_EQ(diff_images(black2x2(), other2x2(), 0).frac_over, 0.75);
  EXPECT_DOUBLE_EQ(diff_images(black2x2(), other2x2(), 255).frac_over, 0.0);
  const ImageDiff ab = diff_images(black2x2(), other2x2());
  const ImageDiff ba = diff_images(other2x2(), black2x2());
  EXPECT_EQ(ab.mae, ba.mae);
  EXPECT_EQ(ab.rmse, ba.rmse);
  EXPECT_EQ(ab.max_abs, ba.max_abs);
}

TEST(DiffImages, PsnrOfUniformErrorOfOneLevel) {
  const Image8 a = make(1, 1, {100, 100, 100});
  const Image8 b = make(1, 1, {101, 99, 101});
  const ImageDiff d = diff_images(a, b);
  EXPECT_DOUBLE_EQ(d.mae, 1.0);
  EXPECT_DOUBLE_EQ(d.rmse, 1.0);
  EXPECT_DOUBLE_EQ(d.psnr, 20 * std::log10(255.0));
  EXPECT_DOUBLE_EQ(d.frac_identical, 0.0);
}

TEST(DiffImages, IdenticalImages) {
  const ImageDiff d = diff_images(other2x2(), other2x2());
  EXPECT_EQ(d.mae, 0.0);
  EXPECT_EQ(d.rmse, 0.0);
  EXPECT_TRUE(std::isinf(d.psnr) && d.psnr > 0);
  EXPECT_EQ(d.max_abs, 0);
  EXPECT_EQ(d.frac_over, 0.0);
  EXPECT_EQ(d.frac_identical, 1.0);
}

TEST(DiffImages, SizeMismatchNamesBothSizes) {
  try {
    diff_images(black2x2(), make(3, 2, std::vector<uint8_t>(18, 0)));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("2x2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("3x2"), std::string::npos) << msg;
  }
}

TEST(DiffImages, RejectsInconsistentBuffer) {
  EXPECT_THROW(diff_images(black2x2(), make(2, 2, std::vector<uint8_t>(11, 0))),
               std::invalid_argument);
}

TEST(Downsample, FourByFourToTwoByTwo) {
  // Channel 0 holds r, channel 1 is constant 7, channel 2 holds b: one 1 in the top-left block
  // (mean 0.25 -> 0) and two in the top-right block (mean 0.5 -> 1).
  const uint8_t r[16] = {0,   4,   10, 10,  //
                         8,   4,   10, 11,  //
                         255, 255, 1,  2,   //
                         255, 254, 3,  4};
  const uint8_t b[16] = {1, 0, 1, 1,  //
                         0, 0, 0, 0,  //
                         0, 0, 0, 0,  //
                         0, 0, 0, 0};
  Image8 img = make(4, 4, {});
  for (int i = 0; i < 16; ++i) img.rgb.insert(img.rgb.end(), {r[i], 7, b[i]});
  const Image8 small = downsample(img, 2);
  EXPECT_EQ(small.width, 2);
  EXPECT_EQ(small.height, 2);
  // Means: 4, 10.25 -> 10, 254.75 -> 255, 2.5 -> 3 (halves round up).
  EXPECT_EQ(small.rgb, (std::vector<uint8_t>{4, 7, 0, 10, 7, 1, 255, 7, 0, 3, 7, 0}));
}

TEST(Downsample, FactorOneIsIdentityAndPartialBlocksAreDropped) {
  const Image8 img = other2x2();
  EXPECT_EQ(downsample(img, 1).rgb, img.rgb);
  Image8 odd = make(3, 3, {});
  for (int i = 0; i < 9; ++i) odd.rgb.insert(odd.rgb.end(), {uint8_t(i * 10), 0, 0});
  const Image8 small = downsample(odd, 2);
  EXPECT_EQ(small.width, 1);
  EXPECT_EQ(small.height, 1);
  EXPECT_EQ(small.rgb, (std::vector<uint8_t>{20, 0, 0}));  // (0 + 10 + 30 + 40) / 4.
  EXPECT_EQ(downsample(odd, 4).rgb.size(), 0u);
  EXPECT_THROW(downsample(odd, 0), std::invalid_argument);
}

TEST(DifferenceImage, ScalesMaxChannelDifferenceAndClamps) {
  const Image8 d = difference_image(black2x2(), other2x2());
  EXPECT_EQ(d.width, 2);
  EXPECT_EQ(d.height, 2);
  EXPECT_EQ(d.rgb, (std::vector<uint8_t>{0, 0, 0, 40, 40, 40, 20, 20, 20, 255, 255, 255}));
  const Image8 g = difference_image(black2x2(), other2x2(), 0.25);  // 2.5 -> 3, 1.25 -> 1.
  EXPECT_EQ(g.rgb, (std::vector<uint8_t>{0, 0, 0, 3, 3, 3, 1, 1, 1, 64, 64, 64}));
  const Image8 inf = difference_image(black2x2(), other2x2(), INFINITY);
  EXPECT_EQ(inf.rgb[0], 0);
  EXPECT_EQ(inf.rgb[3], 255);
  EXPECT_THROW(difference_image(black2x2(), other2x2(), -1), std::invalid_argument);
  EXPECT_THROW(difference_image(black2x2(), make(1, 1, {0, 0, 0})), std::invalid_argument);
}

}  // namespace
}  // namespace rt
