// Materials in the loader (src/scene/loader/materials.cpp): references to materials, ids with
// white space, and the older dialect of the material elements.
#include <gtest/gtest.h>

#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "support/loader_fixture.h"

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

}  // namespace
}  // namespace rt
