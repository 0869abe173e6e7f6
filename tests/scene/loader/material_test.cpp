// Materials in the loader (src/scene/loader/materials.cpp): references to materials, ids with
// white space, the older dialect of the material elements, <BRDFs> and the materials that
// use them, and degamma.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cl/material/brdf.h"

#include "scene/scene.h"
#include "support/loader_fixture.h"
#include "support/look_at_scene.h"
#include "util/errors.h"

namespace rt {
namespace {

using namespace test;

TEST_F(LoaderErrors, MaterialIdThatDoesNotExist) {
  expect_error({{"<Material>1</Material>\n            <Faces>", "<Material>7</Material><Faces>"}},
               {"Mesh id=1 > Material", "'7'"});
  // Whitespace around the id is trimmed, both in the message and the lookup.
  expect_error(
      {{"<Material>1</Material>\n            <Center>", "<Material>\n  7  </Material><Center>"}},
      {"Sphere id=1 > Material", "'7'"});
  expect_error(
      {{"<Material>1</Material>\n            <Indices>", "<Material></Material><Indices>"}},
      {"Triangle id=1 > Material", "''"});
}

TEST_F(LoaderAccepts, MaterialIdWithWhitespace) {
  SceneDesc s = load_scene(scene(
      {{"<Center>8</Center>", "<Center> 8\n</Center>"},
       {"<Material>1</Material>\n            <Center>", "<Material>\n   1 </Material><Center>"}}));
  EXPECT_EQ(s.objects.at(2).material, 0);
}

TEST_F(LoaderAccepts, OlderMaterialDialect) {
  const char* mats = R"(<Material id="2"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material>
        <Material id="3"><MirrorReflectance>1 1 1</MirrorReflectance></Material>
        <Material id="4"><Transparency>0.5 0.5 0.5</Transparency><RefractionIndex>1.5</RefractionIndex></Material>
    </Materials>)";
  SceneDesc old = load_scene(scene({{"</Materials>", mats}}));
  ASSERT_EQ(old.materials.size(), 4u);
  EXPECT_EQ(old.materials[0].type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(old.materials[1].type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(old.materials[2].type, RT_MATERIAL_MIRROR);
  EXPECT_EQ(old.materials[3].type, RT_MATERIAL_DIELECTRIC);
  // Without <Transparency> anywhere the file is of the newer kind: no type, no mirror.
  SceneDesc newer = load_scene(write(
      "newer.xml",
      edited(kTinyScene, {{"</Materials>",
                           replaced_all(mats, "<Transparency>0.5 0.5 0.5</Transparency>", "")}})));
  EXPECT_EQ(newer.materials.at(2).type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(newer.materials.at(3).type, RT_MATERIAL_PLAIN);
}

TEST(LoaderHw56, Brdfs) {
  LookAtParts p;
  EXPECT_EQ(load_look_at(p).materials[0].brdf, RT_BRDF_ORIGINAL_BLINN_PHONG);
  p.brdfs = R"(<BRDFs><ModifiedPhong id="1" normalized="true"><Exponent>50</Exponent>
    </ModifiedPhong><TorranceSparrow id="2" kdfresnel="true"><Exponent>20</Exponent>
    </TorranceSparrow></BRDFs>)";
  p.material = R"(BRDF="1")";
  Material m = load_look_at(p).materials[0];
  EXPECT_EQ(m.brdf, RT_BRDF_MODIFIED_PHONG);
  EXPECT_EQ(m.brdf_flags, RT_BRDF_NORMALIZED);
  EXPECT_EQ(m.phong_exponent, 50.0f);  // The BRDF's exponent replaces PhongExponent.
  p.material = R"(BRDF="2")";
  m = load_look_at(p).materials[0];
  EXPECT_EQ(m.brdf, RT_BRDF_TORRANCE_SPARROW);
  EXPECT_EQ(m.brdf_flags, RT_BRDF_KD_FRESNEL);
  EXPECT_EQ(m.phong_exponent, 20.0f);
  p.material = R"(BRDF="3")";
  expect_look_at_error(p, "BRDF='3' names no BRDF");
  p.brdfs = R"(<BRDFs><Lafortune id="1"/></BRDFs>)";
  p.material = "";
  expect_look_at_error(p, "Lafortune id=1: unknown BRDF type");
  p.brdfs = R"(<BRDFs><ModifiedPhong id="1" normalized="yes"/></BRDFs>)";
  expect_look_at_error(p, "normalized='yes' must be true or false");
}

TEST(LoaderHw56, Degamma) {
  LookAtParts p;
  p.material = R"(degamma="true")";
  Material m = load_look_at(p).materials[0];
  EXPECT_EQ(m.ambient.x, 1.0f);
  EXPECT_EQ(m.diffuse.x, std::pow(0.5f, 2.2f));
  EXPECT_EQ(m.specular.y, std::pow(0.25f, 2.2f));
}

}  // namespace
}  // namespace rt
