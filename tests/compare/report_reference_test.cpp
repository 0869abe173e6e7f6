// The reference criterion shared by tests/course/reference_check.cpp and `compare reference`
// (its thresholds at their edges, the course_scenes.txt syntax and look-up), and
// `compare summary` on files with known contents.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/moments.h"
#include "reference_criterion.h"
#include "summary.h"

namespace {

rt::Image8 Flat(int w, int h, uint8_t v) {
  rt::Image8 img;
  img.width = w;
  img.height = h;
  img.rgb.assign(static_cast<size_t>(w) * h * 3, v);
  return img;
}

TEST(ReferenceCriterion, Hw12NeedsTheIdenticalShare) {
  rt::Image8 ref = Flat(100, 100, 120), render = ref;
  cmp::ReferenceCriterion c;  // hw12: at least 99.9 % of the 10,000 pixels identical.
  for (int i = 0; i < 10; ++i) render.rgb[i * 300] += 1;
  cmp::ReferenceResult r = cmp::check_reference(render, ref, c, false);
  EXPECT_TRUE(r.pass);
  EXPECT_DOUBLE_EQ(r.min_identical, 99.9);
  render.rgb[10 * 300] += 1;  // The 11th pixel: 99.89 %.
  EXPECT_FALSE(cmp::check_reference(render, ref, c, false).pass);
  c.min_identical = 99.85;  // hw12:99.85, as for hw1 spheres_mirror.
  EXPECT_TRUE(cmp::check_reference(render, ref, c, false).pass);
  c.double_min_identical = 99.95;  // Applies only to a render in double.
  EXPECT_TRUE(cmp::check_reference(render, ref, c, false).pass);
  EXPECT_FALSE(cmp::check_reference(render, ref, c, true).pass);
}

TEST(ReferenceCriterion, Hw3BoundsTheMeanBias) {
  rt::Image8 ref = Flat(64, 64, 100), render = ref;
  cmp::ReferenceCriterion c;
  c.kind = "hw3";
  // 4 % of the values one level up: bias +0.04, within 0.05.
  for (size_t i = 0; i < render.rgb.size(); i += 25) render.rgb[i] += 1;
  cmp::ReferenceResult r = cmp::check_reference(render, ref, c, false);
  EXPECT_NEAR(r.bias, 0.04, 1e-3);
  EXPECT_TRUE(r.pass);
  for (size_t i = 0; i < render.rgb.size(); i += 50) render.rgb[i + 1] += 1;  // +0.06.
  EXPECT_FALSE(cmp::check_reference(render, ref, c, false).pass);
  c.max_bias = 0.4;  // hw3:0.4.
  EXPECT_TRUE(cmp::check_reference(render, ref, c, false).pass);
  EXPECT_THROW(cmp::check_reference(Flat(8, 8, 0), ref, c, false), std::invalid_argument);
}

TEST(ReferenceCriterion, BlockBoundsTheDownsampledError) {
  rt::Image8 ref = Flat(16, 16, 100), render = ref;
  // A checkerboard of +-3: no bias, 4x4 blocks average it out, every pixel differs.
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) render.rgb[(y * 16 + x) * 3 + c] = (x + y) % 2 ? 103 : 97;
  cmp::ReferenceCriterion block;
  block.kind = "block";
  EXPECT_TRUE(cmp::check_reference(render, ref, block, false).pass);
  cmp::ReferenceCriterion hw12;  // Pixel for pixel it fails.
  EXPECT_FALSE(cmp::check_reference(render, ref, hw12, false).pass);
}

TEST(ReferenceCriterion, ParsesTheCourseScenesSyntax) {
  cmp::ReferenceCriterion c;
  std::string error;
  ASSERT_TRUE(cmp::parse_criterion("hw12:99.88", &c, &error)) << error;
  EXPECT_EQ(c.kind, "hw12");
  EXPECT_DOUBLE_EQ(c.min_identical, 99.88);
  ASSERT_TRUE(cmp::parse_criterion("hw12,double:99.78", &c, &error)) << error;
  EXPECT_DOUBLE_EQ(c.min_identical, 0);
  EXPECT_DOUBLE_EQ(c.double_min_identical, 99.78);
  ASSERT_TRUE(cmp::parse_criterion("hw3:0.4", &c, &error)) << error;
  EXPECT_DOUBLE_EQ(c.max_bias, 0.4);
  ASSERT_TRUE(cmp::parse_criterion("block:2.6", &c, &error)) << error;
  EXPECT_DOUBLE_EQ(c.max_block_mae, 2.6);
  EXPECT_FALSE(cmp::parse_criterion("hw4", &c, &error));
  EXPECT_NE(error.find("unknown kind 'hw4'"), std::string::npos) << error;
  EXPECT_FALSE(cmp::parse_criterion("hw12:lots", &c, &error));
  EXPECT_NE(error.find("'lots' is not a number"), std::string::npos) << error;
  EXPECT_FALSE(cmp::parse_criterion("hw12,single:3", &c, &error));
  EXPECT_NE(error.find("unknown part 'single:3'"), std::string::npos) << error;
}

TEST(ReferenceCriterion, LooksTheReferenceUpByItsPath) {
  std::string list = testing::TempDir() + "/course_scenes.txt";
  std::ofstream(list) << "# comment\n"
                         "hw1.spheres hw1/spheres.xml hw1/reference/spheres.png hw12:99.88 -x\n"
                         "hw3.area hw3/area.xml hw3/reference/area.png hw3\n";
  std::string name, field;
  ASSERT_TRUE(
      cmp::find_course_criterion(list, "/some/scenes/hw3/reference/area.png", &name, &field));
  EXPECT_EQ(name, "hw3.area");
  EXPECT_EQ(field, "hw3");
  ASSERT_TRUE(cmp::find_course_criterion(list, "hw1/reference/spheres.png", &name, &field));
  EXPECT_EQ(field, "hw12:99.88");
  // A path that only ends in the same characters is no match.
  EXPECT_FALSE(cmp::find_course_criterion(list, "/x/myhw3/reference/area.png", &name, &field));
  EXPECT_THROW(cmp::find_course_criterion(list + ".missing", "a.png", &name, &field),
               std::runtime_error);
}

TEST(Summary, DescribesAPngAndAMomentFileWithNaN) {
  std::string dir = testing::TempDir() + "/summary_test";
  std::filesystem::remove_all(dir);  // A moment file left by an earlier run would be read.
  std::filesystem::create_directories(dir);
  rt::Image8 img = Flat(4, 2, 10);
  img.rgb[0] = 250;
  rt::write_png(dir + "/img.png", img);
  std::string s = cmp::summarise(dir + "/img.png");
  EXPECT_NE(s.find("4x2, 8-bit RGB PNG"), std::string::npos) << s;
  EXPECT_NE(s.find("R: range [10, 250], mean 40, NaN 0, Inf 0"), std::string::npos) << s;
  EXPECT_NE(s.find("no moment file beside it"), std::string::npos) << s;
  rt::MomentImage m;
  m.width = 4;
  m.height = 2;
  m.info.spp = 9;
  m.mean.assign(24, 1.0f);
  m.mean[3] = NAN;
  m.mean[4] = INFINITY;
  m.var.assign(24, 0.5f);
  m.count.assign(8, 9);
  m.count[7] = 7;
  m.first_t.assign(8, 1.0f);
  m.instance.assign(8, 0);
  m.primitive.assign(8, 0);
  m.normal.assign(24, 0.0f);
  rt::write_moments(dir + "/img.moments.exr", m);
  s = cmp::summarise(dir + "/img.png");
  EXPECT_NE(s.find("samples per pixel: min 7, mean 8.75, max 9"), std::string::npos) << s;
  EXPECT_NE(s.find("R: range [1, 1], mean 1, NaN 1, Inf 0"), std::string::npos) << s;
  EXPECT_NE(s.find("G: range [1, 1], mean 1, NaN 0, Inf 1"), std::string::npos) << s;
  EXPECT_THROW(cmp::summarise(dir + "/absent.png"), std::runtime_error);
}

}  // namespace
