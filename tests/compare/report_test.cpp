// The parts of `compare report`: the colour map, the embedded images, the choice of the
// worst tiles, and the verdicts in words on synthetic images whose truth is known
// (identical, noise alone, a bias planted in one tile, plain PNGs without moments).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "colormap.h"
#include "embed.h"
#include "report_model.h"

namespace {

double Luminance(const uint8_t rgb[3]) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

TEST(ColourMap, ViridisEndsAndMiddleMatchMatplotlib) {
  uint8_t c[3];
  cmp::viridis(0, c);
  EXPECT_EQ(c[0], 68);
  EXPECT_EQ(c[1], 1);
  EXPECT_EQ(c[2], 84);
  cmp::viridis(1, c);
  EXPECT_EQ(c[0], 253);
  EXPECT_EQ(c[1], 231);
  EXPECT_EQ(c[2], 37);
  // matplotlib's viridis(0.5) is (33, 145, 140): the ten-stop table is within 2 levels.
  cmp::viridis(0.5, c);
  EXPECT_NEAR(c[0], 33, 2);
  EXPECT_NEAR(c[1], 145, 2);
  EXPECT_NEAR(c[2], 140, 2);
  // Out of range and NaN clamp to the ends.
  uint8_t lo[3], nan[3], hi[3];
  cmp::viridis(-3, lo);
  cmp::viridis(NAN, nan);
  cmp::viridis(7, hi);
  EXPECT_EQ(lo[1], 1);
  EXPECT_EQ(nan[1], 1);
  EXPECT_EQ(hi[1], 231);
}

TEST(ColourMap, LightnessRisesMonotonically) {
  // The property that makes the map readable: a larger difference is always lighter.
  uint8_t prev[3];
  cmp::viridis(0, prev);
  for (int i = 1; i <= 100; ++i) {
    uint8_t c[3];
    cmp::viridis(i / 100.0, c);
    EXPECT_GT(Luminance(c), Luminance(prev)) << "t = " << i / 100.0;
    std::copy(c, c + 3, prev);
  }
}

TEST(ColourMap, MapScalesAndBarRunsFromZeroToOne) {
  rt::Image8 m = cmp::colour_map(3, 1, {0.0f, 5.0f, 20.0f}, 10.0);
  uint8_t mid[3], top[3];
  cmp::viridis(0.5, mid);
  cmp::viridis(1, top);
  EXPECT_EQ(m.rgb[3 + 1], mid[1]);
  EXPECT_EQ(m.rgb[6 + 1], top[1]);  // 20 / 10 saturates.
  rt::Image8 bar = cmp::colour_bar(256, 2);
  EXPECT_EQ(bar.width, 256);
  EXPECT_EQ(bar.rgb[1], 1);
  EXPECT_EQ(bar.rgb[255 * 3 + 1], 231);
}

TEST(Embed, Base64AndPngDataUri) {
  EXPECT_EQ(cmp::base64({'M', 'a', 'n'}), "TWFu");
  EXPECT_EQ(cmp::base64({'M', 'a'}), "TWE=");
  EXPECT_EQ(cmp::base64({'M'}), "TQ==");
  EXPECT_EQ(cmp::base64({}), "");
  rt::Image8 img;
  img.width = img.height = 2;
  img.rgb.assign(12, 200);
  // The PNG signature 89 50 4E 47 0D 0A 1A 0A in base64.
  EXPECT_EQ(cmp::png_data_uri(img).rfind("data:image/png;base64,iVBORw0KGgo", 0), 0u);
  EXPECT_EQ(cmp::html_escape("<a href=\"x\">&'</a> \xc3\xa9"),
            "&#60;a href=&#34;x&#34;&#62;&#38;&#39;&#60;/a&#62; \xc3\xa9");
}

TEST(Embed, CropAndNearestNeighbourEnlargement) {
  rt::Image8 img;
  img.width = 3;
  img.height = 2;
  for (int i = 0; i < 6; ++i) img.rgb.insert(img.rgb.end(), 3, static_cast<uint8_t>(10 * i));
  rt::Image8 c = cmp::crop(img, 1, 1, 5, 5);  // Clipped to 2 x 1: pixels 4 and 5.
  ASSERT_EQ(c.width, 2);
  ASSERT_EQ(c.height, 1);
  EXPECT_EQ(c.rgb[0], 40);
  EXPECT_EQ(c.rgb[3], 50);
  rt::Image8 e = cmp::enlarge(c, 3);
  ASSERT_EQ(e.width, 6);
  ASSERT_EQ(e.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 6; ++x) EXPECT_EQ(e.rgb[(y * 6 + x) * 3], x < 3 ? 40 : 50);
}

cmp::TileFigures Tile(double mean_abs, int max_abs, bool tested = false, double p = 1,
                      bool rejected = false) {
  cmp::TileFigures t;
  t.mean_abs = mean_abs;
  t.max_abs = max_abs;
  t.tested = tested;
  t.p = p;
  t.rejected = rejected;
  return t;
}

TEST(WorstTiles, RanksByDifferenceAndLeavesEqualTilesOut) {
  std::vector<cmp::TileFigures> tiles = {Tile(0, 0), Tile(0.5, 3), Tile(2, 9), Tile(0.5, 7),
                                         Tile(0, 0)};
  EXPECT_EQ(cmp::worst_tiles(tiles, 10), (std::vector<size_t>{2, 3, 1}));
  EXPECT_EQ(cmp::worst_tiles(tiles, 2), (std::vector<size_t>{2, 3}));
  EXPECT_TRUE(cmp::worst_tiles({Tile(0, 0)}, 5).empty());
}

TEST(WorstTiles, RejectedFirstThenSmallestP) {
  // A rejected tile outranks a larger but insignificant difference; then p decides, and
  // a tile the test did not look at (equal means, different 8-bit pixels) comes last.
  std::vector<cmp::TileFigures> tiles = {Tile(5, 20, true, 0.3), Tile(0.1, 1, true, 1e-9, true),
                                         Tile(1, 4, true, 0.01), Tile(0.2, 1, true, 1e-12, true),
                                         Tile(9, 30)};
  EXPECT_EQ(cmp::worst_tiles(tiles, 10), (std::vector<size_t>{3, 1, 2, 0, 4}));
}

// A render of a w x h image whose every pixel has expected radiance `level` (plus `bias`
// inside the tile at `bias_x`, `bias_y`), `n` samples of variance `var`: each mean drawn
// around its expectation with the standard error sqrt(var / n).
cmp::Side Render(int w, int h, uint32_t seed, double bias = 0, int bias_x = 0, int bias_y = 0,
                 int tile = 16) {
  const double level = 100, var = 400;
  const uint32_t n = 64;
  cmp::Side s;
  s.path = "render" + std::to_string(seed) + ".png";
  s.has_moments = true;
  rt::MomentImage& m = s.moments;
  m.width = w;
  m.height = h;
  m.info.seed = seed;
  m.info.spp = static_cast<int>(n);
  m.count.assign(m.pixels(), n);
  m.var.assign(m.pixels() * 3, static_cast<float>(var));
  std::mt19937 rng(seed * 7919 + 1);
  std::normal_distribution<double> noise(0, std::sqrt(var / n));
  s.image.width = w;
  s.image.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        bool in = x / tile == bias_x && y / tile == bias_y;
        double v = level + (in ? bias : 0) + noise(rng);
        m.mean.push_back(static_cast<float>(v));
        s.image.rgb.push_back(static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 255.0))));
      }
  return s;
}

TEST(ReportVerdict, IdenticalRendersSayIdentical) {
  cmp::Side a = Render(32, 32, 1), b = a;
  b.path = "copy.png";
  cmp::Analysis r = cmp::analyse(a, b, cmp::ReportOptions{});
  EXPECT_EQ(r.finding, cmp::Finding::kIdentical);
  EXPECT_EQ(r.words.rfind("identical", 0), 0u) << r.words;
  EXPECT_TRUE(r.worst.empty());
  EXPECT_TRUE(r.test.empty());
}

TEST(ReportVerdict, NoiseAloneIsWithinNoise) {
  cmp::Analysis r = cmp::analyse(Render(64, 48, 1), Render(64, 48, 2), cmp::ReportOptions{});
  EXPECT_EQ(r.test, "welch");
  EXPECT_EQ(r.finding, cmp::Finding::kWithinNoise) << r.words;
  EXPECT_EQ(r.words.rfind("within noise", 0), 0u) << r.words;
  EXPECT_EQ(r.tiles.size(), 4u * 3u);
  EXPECT_FALSE(r.worst.empty());  // The noise differs everywhere; nothing is rejected.
  for (const cmp::TileFigures& t : r.tiles) EXPECT_FALSE(t.rejected);
}

TEST(ReportVerdict, PlantedBiasIsNamedByItsTile) {
  // +1.5 levels (0.6 standard errors of one pixel: invisible pixel by pixel) in the tile
  // whose first pixel is (32, 16).
  cmp::Side a = Render(64, 48, 1), b = Render(64, 48, 2, 1.5, 2, 1);
  cmp::Analysis r = cmp::analyse(a, b, cmp::ReportOptions{});
  EXPECT_EQ(r.finding, cmp::Finding::kBiased) << r.words;
  ASSERT_FALSE(r.worst.empty());
  const cmp::TileFigures& worst = r.tiles[r.worst[0]];
  EXPECT_EQ(worst.x, 32);
  EXPECT_EQ(worst.y, 16);
  EXPECT_TRUE(worst.rejected);
  EXPECT_NE(r.words.find("biased here: 1 of 12 tiles"), std::string::npos) << r.words;
  EXPECT_NE(r.words.find("(32, 16)-(47, 31)"), std::string::npos) << r.words;
  EXPECT_NEAR(worst.mean_b[0] - worst.mean_a[0], 1.5, 0.3);
}

TEST(ReportVerdict, EqualSeedsUseThePairedTest) {
  cmp::Side a = Render(32, 32, 5), b = Render(32, 32, 5, 0.5, 1, 1);
  cmp::Analysis r = cmp::analyse(a, b, cmp::ReportOptions{});
  EXPECT_EQ(r.test, "paired");
  EXPECT_EQ(r.finding, cmp::Finding::kBiased) << r.words;
  EXPECT_NE(r.words.find("(16, 16)-(31, 31)"), std::string::npos) << r.words;
}

TEST(ReportVerdict, PlainImagesGetADifferenceSummary) {
  cmp::Side a = Render(64, 40, 1);
  a.has_moments = false;
  cmp::Side b = a;
  b.image.rgb[(5 * 64 + 25) * 3 + 1] += 30;  // One pixel of 2,560, in the tile at (16, 0).
  cmp::Analysis r = cmp::analyse(a, b, cmp::ReportOptions{});
  EXPECT_EQ(r.finding, cmp::Finding::kDiffer);
  EXPECT_NE(r.words.find("largest difference 30 levels"), std::string::npos) << r.words;
  EXPECT_NE(r.words.find("0.0391 % of pixels differ"), std::string::npos) << r.words;
  ASSERT_EQ(r.worst.size(), 1u);
  EXPECT_EQ(r.tiles[r.worst[0]].x, 16);
  EXPECT_EQ(r.tiles[r.worst[0]].max_abs, 30);
  EXPECT_EQ(r.scale, 1);  // The 99.9th percentile: the one pixel saturates the map.
}

TEST(ReportVerdict, SizeMismatchNamesBothFiles) {
  cmp::Side a = Render(8, 8, 1), b = Render(8, 6, 2);
  try {
    cmp::analyse(a, b, cmp::ReportOptions{});
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_STREQ(e.what(),
                 "render1.png is 8x8, render2.png is 8x6: the images must be the same size");
  }
}

}  // namespace
