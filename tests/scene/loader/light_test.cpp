// Lights in the loader (src/scene/loader/lights.cpp): area lights given by a normal and a size or
// by edge vectors, and negative light values.
#include <gtest/gtest.h>

#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "support/loader_fixture.h"

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

}  // namespace
}  // namespace rt
