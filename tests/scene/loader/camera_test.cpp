// Cameras in the loader (src/scene/loader/cameras.cpp): required elements, degenerate gaze and up
// vectors, lookAt cameras (with a <GazePoint> or a <Gaze>), resolution, near plane, sample
// counts, and <Tonemap> with its bad values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/scene.h"
#include "support/loader_fixture.h"
#include "support/look_at_scene.h"
#include "util/errors.h"

namespace rt {
namespace {

using namespace test;

TEST_F(LoaderErrors, MissingRequiredCameraElement) {
  for (const char* line :
       {"<Position>0 0 0</Position>\n            <Gaze>", "<Gaze>0 0 -1</Gaze>", "<Up>0 1 0</Up>",
        "<NearPlane>-1 1 -0.5 0.5</NearPlane>", "<NearDistance>1</NearDistance>",
        "<ImageResolution>16 8</ImageResolution>", "<ImageName>simple.png</ImageName>"}) {
    std::string l = line;
    std::string name = l.substr(1, l.find('>') - 1);
    SCOPED_TRACE(name);
    // The Position line is written with the start of the Gaze line to keep it unique.
    std::string keep = l.find("\n") != std::string::npos ? "<Gaze>" : "";
    expect_error({{l, keep}}, {"Camera id=1", "missing <" + name + ">"});
  }
}

TEST_F(LoaderErrors, ZeroGaze) {
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze>0 0 0</Gaze>"}},
               {"Camera id=1 > Gaze", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, ZeroUp) {
  expect_error({{"<Up>0 1 0</Up>", "<Up>0 0 0</Up>"}}, {"Camera id=1 > Up", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, UpParallelToGaze) {
  expect_error({{"<Up>0 1 0</Up>", "<Up>0 0 2</Up>"}}, {"Camera id=1 > Up", "'0 0 2'", "parallel"});
}

TEST_F(LoaderErrors, LookAtGazePointAtPosition) {
  expect_error({{"<Camera id=\"1\">", "<Camera id=\"1\" type=\"lookAt\">"},
                {"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 0</GazePoint><FovY>45</FovY>"}},
               {"Camera id=1 > GazePoint", "'0 0 0'", "Position"});
}

TEST_F(LoaderErrors, GazePointWithoutLookAt) {
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 -1</GazePoint><FovY>45</FovY>"}},
               {"Camera id=1", "missing <Gaze>", "lookAt"});
}

TEST_F(LoaderErrors, BadResolutionNearDistanceAndSamples) {
  expect_error(
      {{"<ImageResolution>16 8</ImageResolution>", "<ImageResolution>16 0</ImageResolution>"}},
      {"Camera id=1 > ImageResolution", "'16 0'"});
  expect_error(
      {{"<ImageResolution>16 8</ImageResolution>", "<ImageResolution>16.5 8</ImageResolution>"}},
      {"Camera id=1 > ImageResolution", "'16.5 8'"});
  expect_error({{"<NearDistance>1</NearDistance>", "<NearDistance>-1</NearDistance>"}},
               {"Camera id=1 > NearDistance", "'-1'"});
  expect_error({{"<ImageName>simple.png</ImageName>", "<ImageName>   </ImageName>"}},
               {"Camera id=1 > ImageName", "empty"});
}

TEST_F(LoaderErrors, NonSquareNumSamples) {
  expect_error({{"<ImageName>", "<NumSamples>8</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'8'", "not a perfect square"});
  expect_error({{"<ImageName>", "<NumSamples>0</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'0'"});
  expect_error({{"<ImageName>", "<NumSamples>4.5</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'4.5'"});
}

TEST_F(LoaderAccepts, PaddedImageNameTrimmed) {
  SceneDesc s = load_scene(scene({{"<ImageName>simple.png", "<ImageName>  x.png  "}}));
  EXPECT_EQ(s.cameras.at(0).image_name, "x.png");
}

TEST_F(LoaderAccepts, FiveNumberNearPlane) {
  SceneDesc s = load_scene(scene({{"-1 1 -0.5 0.5</NearPlane>", "-1 1 -0.5 0.5 1</NearPlane>"}}));
  const CameraDesc& c = s.cameras.at(0);
  EXPECT_EQ(c.left, -1);
  EXPECT_EQ(c.right, 1);
  EXPECT_EQ(c.bottom, -0.5);
  EXPECT_EQ(c.top, 0.5);
}

TEST_F(LoaderAccepts, LookAtCamera) {
  SceneDesc s =
      load_scene(scene({{"<Camera id=\"1\">", "<Camera id=\"1\" type=\"lookAt\">"},
                        {"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 -5</GazePoint>"},
                        {"<NearPlane>-1 1 -0.5 0.5</NearPlane>", "<FovY>60</FovY>"},
                        {"<NearDistance>1</NearDistance>", "<NearDistance>2</NearDistance>"}}));
  const CameraDesc& c = s.cameras.at(0);
  double top = 2 * std::tan(30 * M_PI / 180);
  EXPECT_NEAR(c.top, top, 1e-12);
  EXPECT_NEAR(c.bottom, -top, 1e-12);
  EXPECT_NEAR(c.right, top * 16 / 8, 1e-12);
  EXPECT_NEAR(c.left, -top * 2, 1e-12);
  EXPECT_EQ(c.gaze.z, -5);
}

TEST_F(LoaderAccepts, CameraOutsideCameras) {
  // Files of 2017 have no <Cameras> wrapper.
  std::string xml = edited(kTinyScene, {{"    <Cameras>\n", ""}, {"    </Cameras>\n", ""}});
  SceneDesc s = load_scene(write("scene.xml", xml));
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].image_name, "simple.png");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
  expect_error(write("bad.xml", edited(xml, {{"<Up>0 1 0</Up>", "<Up>0 0 0</Up>"}})),
               {": Camera id=1 > Up: '0 0 0'"});
}

const char* kTonemap = R"(<Tonemap><TMO>Photographic</TMO><TMOOptions>0.01 2</TMOOptions>
  <Saturation>0.8</Saturation><Gamma>2.4</Gamma></Tonemap>)";

TEST(LoaderHw56, Tonemap) {
  LookAtParts p;
  EXPECT_FALSE(load_look_at(p).cameras[0].tonemap);
  p.tonemap = kTonemap;
  CameraDesc c = load_look_at(p).cameras[0];
  ASSERT_TRUE(c.tonemap);
  EXPECT_EQ(c.tonemap_params.key, 0.01);
  EXPECT_EQ(c.tonemap_params.burn_percent, 2);
  EXPECT_EQ(c.tonemap_params.saturation, 0.8);
  EXPECT_EQ(c.tonemap_params.gamma, 2.4);
}

TEST(LoaderHw56, TonemapErrors) {
  LookAtParts p;
  p.tonemap = "<Tonemap><TMO>ACES</TMO><TMOOptions>0.18 1</TMOOptions></Tonemap>";
  expect_look_at_error(p, "TMO: 'ACES' is not a known operator");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0 1</TMOOptions></Tonemap>";
  expect_look_at_error(p, "key value must be positive");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 100</TMOOptions></Tonemap>";
  expect_look_at_error(p, "burn-out percentage");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18</TMOOptions></Tonemap>";
  expect_look_at_error(p, "TMOOptions");
  p.tonemap =
      "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions>"
      "<Gamma>0</Gamma></Tonemap>";
  expect_look_at_error(p, "Gamma: '0' must be positive");
}

// hw6's lookAt cameras give a direction; it must equal the GazePoint form.
TEST(LoaderHw56, LookAtWithGaze) {
  LookAtParts p;
  CameraDesc point = load_look_at(p).cameras[0];
  p.camera = "<Gaze>0 0 -2</Gaze>";
  CameraDesc dir = load_look_at(p).cameras[0];
  EXPECT_EQ(point.gaze.z / std::fabs(point.gaze.z), -1.0);
  EXPECT_EQ(dir.gaze.x, 0.0);
  EXPECT_EQ(dir.gaze.z, -2.0);
  EXPECT_EQ(point.top, dir.top);
  p.camera = "";
  expect_look_at_error(p, "GazePoint");
}

}  // namespace
}  // namespace rt
