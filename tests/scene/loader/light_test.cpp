// Lights in the loader (src/scene/loader/lights.cpp): area lights given by a normal and a size or
// by edge vectors, negative light values, and directional and spot lights with their bad
// values.
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

const char* kAreaLight = R"(<AreaLight id="1">
            <Position>0 1 -2</Position>
            <Normal>0 -1 0</Normal>
            <Size>2</Size>
            <Radiance>10 10 10</Radiance>
        </AreaLight>
    </Lights>)";

TEST_F(LoaderErrors, ZeroAreaLightNormal) {
  expect_error({{"</Lights>", replaced_all(kAreaLight, "0 -1 0", "0 0 0")}},
               {"AreaLight id=1 > Normal", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, NegativeAreaLightSize) {
  expect_error({{"</Lights>", replaced_all(kAreaLight, "<Size>2", "<Size>-2")}},
               {"AreaLight id=1 > Size", "'-2'"});
}

TEST_F(LoaderErrors, NegativeLightValues) {
  expect_error({{"<Intensity>1000 1000 1000</Intensity>", "<Intensity>1000 -1 1000</Intensity>"}},
               {"PointLight id=1 > Intensity", "'1000 -1 1000'", "negative"});
  expect_error({{"</Lights>", replaced_all(kAreaLight, "10 10 10", "10 10 -0.5")}},
               {"AreaLight id=1 > Radiance", "'10 10 -0.5'", "negative"});
  expect_error(
      {{"<AmbientLight>25 25 25</AmbientLight>", "<AmbientLight>-25 25 25</AmbientLight>"}},
      {"AmbientLight", "'-25 25 25'", "negative"});
}

TEST_F(LoaderAccepts, EdgeVectorAreaLight) {
  SceneDesc s = load_scene(scene({{"</Lights>", R"(<AreaLight id="1">
            <Position>1 2 3</Position>
            <EdgeVector1>2 0 0</EdgeVector1>
            <EdgeVector2>0 0 3</EdgeVector2>
            <Intensity>5 6 7</Intensity>
        </AreaLight></Lights>)"}}));
  ASSERT_EQ(s.area_lights.size(), 1u);
  const AreaLight& a = s.area_lights[0];
  EXPECT_FLOAT_EQ(a.area, 6);
  EXPECT_FLOAT_EQ(a.corner.x, 1);
  EXPECT_FLOAT_EQ(a.corner.z, 3);
  EXPECT_FLOAT_EQ(a.edge2.z, 3);
  EXPECT_FLOAT_EQ(std::fabs(a.normal.y), 1);
  EXPECT_FLOAT_EQ(a.radiance.y, 6);
}

TEST_F(LoaderAccepts, SquareAreaLight) {
  SceneDesc s = load_scene(scene({{"</Lights>", kAreaLight}}));
  ASSERT_EQ(s.area_lights.size(), 1u);
  const AreaLight& a = s.area_lights[0];
  EXPECT_FLOAT_EQ(a.area, 4);
  // Centred on Position: corner + (edge1 + edge2) / 2 == Position.
  EXPECT_NEAR(a.corner.y + (a.edge1.y + a.edge2.y) / 2, 1, 1e-6);
  EXPECT_NEAR(a.corner.z + (a.edge1.z + a.edge2.z) / 2, -2, 1e-6);
}

TEST(LoaderHw56, DirectionalAndSpotLights) {
  LookAtParts p;
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 -2</Direction>
    <Radiance>200 100 50</Radiance></DirectionalLight>
    <SpotLight id="1"><Position>1 2 3</Position><Direction>0 -3 0</Direction>
    <Intensity>600 600 600</Intensity><CoverageAngle>90</CoverageAngle>
    <FalloffAngle>60</FalloffAngle></SpotLight>)";
  SceneDesc s = load_look_at(p);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, RT_LIGHT_DIRECTIONAL);
  EXPECT_EQ(s.lights[0].normal.z, -1.0f);  // Normalized.
  EXPECT_EQ(s.lights[0].emission.y, 100.0f);
  EXPECT_EQ(s.lights[1].type, RT_LIGHT_SPOT);
  EXPECT_EQ(s.lights[1].position.z, 3.0f);
  EXPECT_EQ(s.lights[1].normal.y, -1.0f);
  EXPECT_FLOAT_EQ(RT_SPOT_COS_FALLOFF(&s.lights[1]),
                  std::cos(30 * M_PI / 180));  // Half the fall-off.
  EXPECT_FLOAT_EQ(RT_SPOT_COS_COVERAGE(&s.lights[1]),
                  std::cos(45 * M_PI / 180));  // Half the coverage.
}

TEST(LoaderHw56, LightErrors) {
  LookAtParts p;
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 0</Direction>
    <Radiance>1 1 1</Radiance></DirectionalLight>)";
  expect_look_at_error(p, "Direction: '0 0 0' is a zero-length vector");
  p.lights = R"(<DirectionalLight id="1"><Direction>0 0 1</Direction>
    <Radiance>-1 1 1</Radiance></DirectionalLight>)";
  expect_look_at_error(p, "is negative");
  const std::string spot = R"(<SpotLight id="2"><Position>0 0 0</Position>
    <Direction>0 0 1</Direction><Intensity>1 1 1</Intensity>)";
  p.lights = spot + "<CoverageAngle>30</CoverageAngle><FalloffAngle>40</FalloffAngle></SpotLight>";
  expect_look_at_error(p, "SpotLight id=2 > FalloffAngle: '40' must lie in [0, CoverageAngle]");
  p.lights = spot + "<CoverageAngle>0</CoverageAngle><FalloffAngle>0</FalloffAngle></SpotLight>";
  expect_look_at_error(p, "CoverageAngle: '0' must lie in (0, 360]");
  p.lights = spot + "<CoverageAngle>30</CoverageAngle></SpotLight>";
  expect_look_at_error(p, "FalloffAngle");
}

}  // namespace
}  // namespace rt
