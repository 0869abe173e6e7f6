// The scene elements of assignments 5 and 6 in the loader: <Tonemap>, <BRDFs> and the
// materials that use them, directional and spot lights, degamma, lookAt cameras with a
// <Gaze>, and their bad values.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "cl/material/brdf.h"
#include "util/errors.h"
#include "scene/scene.h"
#include "support/test_scene.h"

namespace rt {
namespace {

// A minimal scene; CAMERA, LIGHTS, BRDFS and MATERIAL are filled in by each test.
const char* kTemplate = R"(<Scene>
  <Cameras><Camera id="1" type="lookAt"><Position>0 0 5</Position>CAMERA<Up>0 1 0</Up>
    <FovY>45</FovY><NearDistance>1</NearDistance><ImageResolution>8 8</ImageResolution>
    <ImageName>out.exr</ImageName>TONEMAP</Camera></Cameras>
  <Lights>LIGHTS</Lights>
  BRDFS
  <Materials><Material id="1" MATERIAL><AmbientReflectance>1 1 1</AmbientReflectance>
    <DiffuseReflectance>0.5 0.5 0.5</DiffuseReflectance>
    <SpecularReflectance>0.25 0.25 0.25</SpecularReflectance><PhongExponent>3</PhongExponent>
  </Material></Materials>
  <VertexData>0 0 0</VertexData>
  <Objects><Sphere id="1"><Material>1</Material><Center>1</Center><Radius>1</Radius></Sphere>
  </Objects>
</Scene>)";

struct Parts {
  std::string camera = "<GazePoint>0 0 0</GazePoint>", tonemap, lights, brdfs, material;
};

std::string Write(const Parts& p) {
  const std::string xml = test::edited(kTemplate, {{"CAMERA", p.camera},
                                                   {"TONEMAP", p.tonemap},
                                                   {"LIGHTS", p.lights},
                                                   {"BRDFS", p.brdfs},
                                                   {"MATERIAL", p.material}});
  std::string path = testing::TempDir() + "loader_hw56_" + std::to_string(getpid()) + ".xml";
  std::ofstream(path) << xml;
  return path;
}

SceneDesc Load(const Parts& p) {
  std::string path = Write(p);
  SceneDesc s = load_scene(path);
  std::remove(path.c_str());
  return s;
}

void ExpectError(const Parts& p, const std::string& fragment) {
  const std::string path = Write(p);
  test::expect_load_error(path, {fragment});
  std::remove(path.c_str());
}

const char* kTonemap = R"(<Tonemap><TMO>Photographic</TMO><TMOOptions>0.01 2</TMOOptions>
  <Saturation>0.8</Saturation><Gamma>2.4</Gamma></Tonemap>)";

TEST(LoaderHw56, Tonemap) {
  Parts p;
  EXPECT_FALSE(Load(p).cameras[0].tonemap);
  p.tonemap = kTonemap;
  CameraDesc c = Load(p).cameras[0];
  ASSERT_TRUE(c.tonemap);
  EXPECT_EQ(c.tonemap_params.key, 0.01);
  EXPECT_EQ(c.tonemap_params.burn_percent, 2);
  EXPECT_EQ(c.tonemap_params.saturation, 0.8);
  EXPECT_EQ(c.tonemap_params.gamma, 2.4);
}

TEST(LoaderHw56, TonemapErrors) {
  Parts p;
  p.tonemap = "<Tonemap><TMO>ACES</TMO><TMOOptions>0.18 1</TMOOptions></Tonemap>";
  ExpectError(p, "TMO: 'ACES' is not a known operator");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0 1</TMOOptions></Tonemap>";
  ExpectError(p, "key value must be positive");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 100</TMOOptions></Tonemap>";
  ExpectError(p, "burn-out percentage");
  p.tonemap = "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18</TMOOptions></Tonemap>";
  ExpectError(p, "TMOOptions");
  p.tonemap =
      "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions>"
      "<Gamma>0</Gamma></Tonemap>";
  ExpectError(p, "Gamma: '0' must be positive");
}

// hw6's lookAt cameras give a direction; it must equal the GazePoint form.
TEST(LoaderHw56, LookAtWithGaze) {
  Parts p;
  CameraDesc point = Load(p).cameras[0];
  p.camera = "<Gaze>0 0 -2</Gaze>";
  CameraDesc dir = Load(p).cameras[0];
  EXPECT_EQ(point.gaze.z / std::fabs(point.gaze.z), -1.0);
  EXPECT_EQ(dir.gaze.x, 0.0);
  EXPECT_EQ(dir.gaze.z, -2.0);
  EXPECT_EQ(point.top, dir.top);
  p.camera = "";
  ExpectError(p, "GazePoint");
}

TEST(LoaderHw56, Brdfs) {
  Parts p;
  EXPECT_EQ(Load(p).materials[0].brdf, RT_BRDF_ORIGINAL_BLINN_PHONG);
  p.brdfs = R"(<BRDFs><ModifiedPhong id="1" normalized="true"><Exponent>50</Exponent>
    </ModifiedPhong><TorranceSparrow id="2" kdfresnel="true"><Exponent>20</Exponent>
    </TorranceSparrow></BRDFs>)";
  p.material = R"(BRDF="1")";
  Material m = Load(p).materials[0];
  EXPECT_EQ(m.brdf, RT_BRDF_MODIFIED_PHONG);
  EXPECT_EQ(m.brdf_flags, RT_BRDF_NORMALIZED);
  EXPECT_EQ(m.phong_exponent, 50.0f);  // The BRDF's exponent replaces PhongExponent.
  p.material = R"(BRDF="2")";
  m = Load(p).materials[0];
  EXPECT_EQ(m.brdf, RT_BRDF_TORRANCE_SPARROW);
  EXPECT_EQ(m.brdf_flags, RT_BRDF_KD_FRESNEL);
  EXPECT_EQ(m.phong_exponent, 20.0f);
  p.material = R"(BRDF="3")";
  ExpectError(p, "BRDF='3' names no BRDF");
  p.brdfs = R"(<BRDFs><Lafortune id="1"/></BRDFs>)";
  p.material = "";
  ExpectError(p, "Lafortune id=1: unknown BRDF type");
  p.brdfs = R"(<BRDFs><ModifiedPhong id="1" normalized="yes"/></BRDFs>)";
  ExpectError(p, "normalized='yes' must be true or false");
}

TEST(LoaderHw56, DirectionalAndSpotLights) {
  Parts p;
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 -2</Direction>
    <Radiance>200 100 50</Radiance></DirectionalLight>
    <SpotLight id="1"><Position>1 2 3</Position><Direction>0 -3 0</Direction>
    <Intensity>600 600 600</Intensity><CoverageAngle>90</CoverageAngle>
    <FalloffAngle>60</FalloffAngle></SpotLight>)";
  SceneDesc s = Load(p);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, RT_LIGHT_DIRECTIONAL);
  EXPECT_EQ(s.lights[0].normal.z, -1.0f);  // Normalized.
  EXPECT_EQ(s.lights[0].emission.y, 100.0f);
  EXPECT_EQ(s.lights[1].type, RT_LIGHT_SPOT);
  EXPECT_EQ(s.lights[1].position.z, 3.0f);
  EXPECT_EQ(s.lights[1].normal.y, -1.0f);
  EXPECT_FLOAT_EQ(s.lights[1].param0, std::cos(30 * M_PI / 180));  // Half the fall-off.
  EXPECT_FLOAT_EQ(s.lights[1].param1, std::cos(45 * M_PI / 180));  // Half the coverage.
}

TEST(LoaderHw56, LightErrors) {
  Parts p;
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 0</Direction>
    <Radiance>1 1 1</Radiance></DirectionalLight>)";
  ExpectError(p, "Direction: '0 0 0' is a zero-length vector");
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 1</Direction>
    <Radiance>-1 1 1</Radiance></DirectionalLight>)";
  ExpectError(p, "is negative");
  const std::string spot = R"(<SpotLight id="2"><Position>0 0 0</Position>
    <Direction>0 0 1</Direction><Intensity>1 1 1</Intensity>)";
  p.lights = spot + "<CoverageAngle>30</CoverageAngle><FalloffAngle>40</FalloffAngle></SpotLight>";
  ExpectError(p, "SpotLight id=2 > FalloffAngle: '40' must lie in [0, CoverageAngle]");
  p.lights = spot + "<CoverageAngle>0</CoverageAngle><FalloffAngle>0</FalloffAngle></SpotLight>";
  ExpectError(p, "CoverageAngle: '0' must lie in (0, 360]");
  p.lights = spot + "<CoverageAngle>30</CoverageAngle></SpotLight>";
  ExpectError(p, "FalloffAngle");
}

TEST(LoaderHw56, Degamma) {
  Parts p;
  p.material = R"(degamma="true")";
  Material m = Load(p).materials[0];
  EXPECT_EQ(m.ambient.x, 1.0f);
  EXPECT_EQ(m.diffuse.x, std::pow(0.5f, 2.2f));
  EXPECT_EQ(m.specular.y, std::pow(0.25f, 2.2f));
}

}  // namespace
}  // namespace rt
