// Image textures read from HDR files (hw5/sphere_point_hdr_texture.xml's .exr): linear
// floats, divided by the Normalizer like 8-bit images and never degammaed, on both devices.
// The course's own grace-new.exr is not in ../shared (SOURCES.md), so the EXRs are made here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "util/errors.h"
#include "io/image_output.h"
#include "support/render_both.h"
#include "support/loader_fixture.h"

namespace rt::test {
namespace {

using HdrTexture = LoaderTest;

// kTinyScene's mesh (the quad) textured by `image` (nearest, replace_kd), with texture
// coordinates spanning the image, and the Normalizer `normalizer`.
Edits Textured(const std::string& image, const std::string& normalizer) {
  return {{"<Objects>", R"(<TexCoordData>0 0  0 1  1 1  1 0  0 0  0 0  0 0  0 0</TexCoordData>
    <Textures><Images><Image id="1">)" +
                            image + R"(</Image></Images>
      <TextureMap id="1" type="image"><ImageId>1</ImageId><DecalMode>replace_kd</DecalMode>
        <Interpolation>nearest</Interpolation><Normalizer>)" +
                            normalizer +
                            R"(</Normalizer></TextureMap></Textures>
    <Objects>)"},
          {"<Faces>", "<Textures>1</Textures><Faces>"}};
}

// An EXR whose every texel is (3, 0.5, 0.25), reflectances beyond an 8-bit image's reach,
// gives the image of the untextured quad with that DiffuseReflectance, bit for bit.
TEST_F(HdrTexture, ConstantExrEqualsTheReflectanceItHolds) {
  const int w = 4, h = 2;
  std::vector<float> rgb;
  for (int i = 0; i < w * h; ++i) rgb.insert(rgb.end(), {3.0f, 0.5f, 0.25f});
  write_image((dir_ / "kd.exr").string(), w, h, rgb);
  SceneDesc textured = load_scene(scene(Textured("kd.exr", "1")));
  // The quad gets a material of its own; the other objects keep material 1.
  SceneDesc plain = load_scene(
      scene({{"</Materials>", R"(<Material id="2"><AmbientReflectance>1 1 1</AmbientReflectance>
        <DiffuseReflectance>3 0.5 0.25</DiffuseReflectance>
        <SpecularReflectance>1 1 1</SpecularReflectance><PhongExponent>1</PhongExponent>
        </Material></Materials>)"},
             {"<Material>1</Material>\n            <Faces>", "<Material>2</Material><Faces>"}}));
  std::vector<float> a = RenderBoth(textured), b = RenderBoth(plain);
  EXPECT_EQ(DifferingValues(a, b), 0u);
  // Beyond 8 bits: some pixel's red exceeds what kd = 1 could give (255 clamps at the PNG).
  float peak = 0;
  for (size_t i = 0; i < a.size(); i += 3) peak = std::max(peak, a[i]);
  EXPECT_GT(peak, 255.0f);
}

// A varied EXR holding an 8-bit image's values divided by 255 gives that image's render,
// bit for bit: the same texel layout (rows, columns, channels) and the same lookup.
TEST_F(HdrTexture, ExrMatchesThe8BitImageItEncodes) {
  if (test_precision_double()) GTEST_SKIP() << "the equality is of float arithmetic";
  const int w = 4, h = 2;
  std::vector<float> png, exr;
  for (int i = 0; i < w * h * 3; ++i) {
    float p = static_cast<float>((i * 37 + 11) % 256);
    png.push_back(p);
    exr.push_back(p * (1.0f / 255.0f));  // As the device divides by the Normalizer.
  }
  write_image((dir_ / "kd.png").string(), w, h, png);
  write_image((dir_ / "kd.exr").string(), w, h, exr);
  std::vector<float> a = RenderBoth(load_scene(scene(Textured("kd.exr", "1"))));
  std::vector<float> b = RenderBoth(load_scene(scene(Textured("kd.png", "255"))));
  EXPECT_EQ(DifferingValues(a, b), 0u);
}

// degamma="true" on a TextureMap (hw6/sponza.xml) decodes an 8-bit image with gamma 2.2
// on its 0..255 scale: the render equals that of an EXR holding the decoded values.
TEST_F(HdrTexture, DegammaDecodesTheImage) {
  const int w = 4, h = 2;
  std::vector<float> png, exr;
  for (int i = 0; i < w * h * 3; ++i) {
    float p = static_cast<float>((i * 53 + 7) % 256);
    png.push_back(p);
    exr.push_back(255.0f * std::pow(p / 255.0f, 2.2f));
  }
  write_image((dir_ / "kd.png").string(), w, h, png);
  write_image((dir_ / "kd.exr").string(), w, h, exr);
  Edits degamma = Textured("kd.png", "255");
  degamma[0].second =
      replaced(degamma[0].second, "type=\"image\"", "type=\"image\" degamma=\"true\"");
  SceneDesc decoded = load_scene(scene(degamma));
  ASSERT_EQ(decoded.images.size(), 1u);
  EXPECT_EQ(decoded.images[0].pixels, exr);
  std::vector<float> a = RenderBoth(decoded);
  std::vector<float> b = RenderBoth(load_scene(scene(Textured("kd.exr", "255"))));
  EXPECT_EQ(DifferingValues(a, b), 0u);
  // Without degamma the image differs: the test can fail.
  EXPECT_GT(DifferingValues(a, RenderBoth(load_scene(scene(Textured("kd.png", "255"))))), 0u);
  degamma[0].second = replaced(degamma[0].second, "degamma=\"true\"", "degamma=\"yes\"");
  expect_error(degamma, {"TextureMap id=1", "degamma 'yes' is neither true nor false"});
}

TEST_F(HdrTexture, BadExrIsOneLine) {
  expect_error(Textured("missing.exr", "1"), {"ImageId", "missing.exr", "cannot read EXR"});
  write_image((dir_ / "neg.exr").string(), 2, 1, {1, 1, 1, 1, -2, 1});
  expect_error(Textured("neg.exr", "1"),
               {"ImageId", "neg.exr", "texel (1, 0) is -2", "must be finite and >= 0"});
}

// The course's scene now stops only at its missing map (SOURCES.md: grace-new.exr).
TEST_F(HdrTexture, CourseSceneNamesItsMissingExr) {
  const std::string path = std::string(RT_SHARED_SCENES_DIR) + "/hw5/sphere_point_hdr_texture.xml";
  if (slurp(path).empty()) GTEST_SKIP() << "course scene missing: " << path;
  expect_error(path, {"ImageId", "grace-new.exr", "cannot read EXR"});
}

}  // namespace
}  // namespace rt::test
