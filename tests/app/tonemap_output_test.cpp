// End to end: a camera with <Tonemap> and an .exr ImageName writes the film as OpenEXR
// and, beside it, the PNG that the photographic operator makes of exactly that film; a
// .png ImageName is written as before and --quantize chooses rounding or truncation.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "image/read_hdr.h"
#include "image/tonemap.h"
#include "io/png_io.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;

// hw5's cube_point_hdr in miniature: a grey cube under a point light, tone mapped.
const char* kScene = R"(<Scene>
  <Cameras><Camera id="1" type="lookAt"><Position>5 5 5</Position><GazePoint>0 0 0</GazePoint>
    <Up>0 1 0</Up><FovY>45</FovY><NearDistance>1</NearDistance>
    <ImageResolution>24 16</ImageResolution><ImageName>NAME</ImageName>
    <Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions><Saturation>1.0</Saturation>
    <Gamma>2.2</Gamma></Tonemap></Camera></Cameras>
  <Lights><AmbientLight>25 25 25</AmbientLight><PointLight id="1"><Position>-5 4 5</Position>
    <Intensity>100000 100000 100000</Intensity></PointLight></Lights>
  <Materials><Material id="1" degamma="true"><AmbientReflectance>0.651 0.389 0.389</AmbientReflectance>
    <DiffuseReflectance>0.651 0.389 0.389</DiffuseReflectance>
    <SpecularReflectance>0.651 0.389 0.389</SpecularReflectance><PhongExponent>1</PhongExponent>
  </Material></Materials>
  <VertexData>-1 -1 -1 1 -1 -1 1 1 -1 -1 1 -1 -1 -1 1 1 -1 1 1 1 1 -1 1 1</VertexData>
  <Objects><Mesh id="1"><Material>1</Material><Faces>
    1 3 2 1 4 3 5 6 7 5 7 8 1 2 6 1 6 5 2 3 7 2 7 6 3 4 8 3 8 7 4 1 5 4 5 8
  </Faces></Mesh></Objects>
</Scene>)";

class TonemapOutput : public rt::test::CliFixture {
 protected:
  int Render(const std::string& image_name, const std::string& flags = "") {
    std::string scene = write("scene.xml", rt::test::replaced(kScene, "NAME", image_name));
    return render(scene, flags).code;
  }
  fs::path Out(const std::string& name) const { return fs::path(out_) / name; }
};

TEST_F(TonemapOutput, ExrAndItsToneMappedPng) {
  ASSERT_EQ(Render("cube.exr"), 0);
  ASSERT_TRUE(fs::exists(Out("cube.exr")));
  ASSERT_TRUE(fs::exists(Out("cube.png")));
  rt::ImageF film = rt::read_exr((Out("cube.exr")).string());
  EXPECT_EQ(film.width, 24);
  EXPECT_EQ(film.height, 16);
  rt::PhotographicParams p;
  p.burn_percent = 1;
  rt::Image8 png = rt::read_png((Out("cube.png")).string());
  EXPECT_EQ(png.rgb, rt::TonemapPhotographic(film, p).rgb);
  // The film is HDR: radiance beyond the PNG's white survives in the EXR.
  float peak = 0;
  for (float v : film.pixels) peak = std::max(peak, v);
  EXPECT_GT(peak, 255.0f);
  for (const std::string& name : output_files())  // No temporary left behind.
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
}

// A .png ImageName ignores <Tonemap> (the specification tone maps HDR outputs only);
// truncation differs from rounding by at most one level, and only downwards.
TEST_F(TonemapOutput, PngNameAndQuantize) {
  ASSERT_EQ(Render("round.png", "--quantize round"), 0);
  ASSERT_EQ(Render("trunc.png"), 0);  // Truncation is the default.
  ASSERT_FALSE(fs::exists(Out("round.exr")));
  rt::Image8 r = rt::read_png((Out("round.png")).string());
  rt::Image8 t = rt::read_png((Out("trunc.png")).string());
  ASSERT_EQ(r.rgb.size(), t.rgb.size());
  int lower = 0;
  for (size_t i = 0; i < r.rgb.size(); ++i) {
    ASSERT_TRUE(t.rgb[i] == r.rgb[i] || t.rgb[i] + 1 == r.rgb[i]) << i;
    lower += t.rgb[i] != r.rgb[i];
  }
  EXPECT_GT(lower, 0);
  EXPECT_NE(Render("bad.png", "--quantize floor"), 0);
}

}  // namespace
