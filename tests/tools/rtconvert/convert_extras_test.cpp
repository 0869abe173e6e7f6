// rtconvert's glTF extras: directional and spot lights through them and through the XML
// writer come back with the same bits (the loader's unit direction, cosines of the half
// cone angles); out-of-range values in a file's extras are refused in one line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "convert.h"
#include "course_extras.h"

namespace rtconvert {
namespace {

namespace fs = std::filesystem;

TEST(ConvertLights, DirectionalAndSpotLightsComeBackBitForBit) {
  char tmpl[] = "/tmp/rtconvert_lights_XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const fs::path dir = tmpl;
  std::ofstream(dir / "l.xml") << R"(<Scene>
  <Cameras><Camera id="1"><Position>0 0 5</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 1 -1 1</NearPlane><NearDistance>2</NearDistance>
    <ImageResolution>8 8</ImageResolution><ImageName>l.png</ImageName></Camera></Cameras>
  <Lights>
    <DirectionalLight id="1"><Direction>1 -2 -3</Direction><Radiance>0.3 0.2 0.1</Radiance>
    </DirectionalLight>
    <SpotLight id="2"><Position>0.5 4 1</Position><Direction>0 -1 0.1</Direction>
      <Intensity>900 800 700</Intensity><CoverageAngle>37.5</CoverageAngle>
      <FalloffAngle>21.25</FalloffAngle></SpotLight>
  </Lights>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material>
  </Materials>
  <VertexData>-1 -1 0 1 -1 0 1 1 0</VertexData>
  <Objects><Mesh id="1"><Material>1</Material><Faces>1 2 3</Faces></Mesh></Objects>
</Scene>)";
  const rt::SceneDesc a = rt::load_scene((dir / "l.xml").string());
  Report r;
  export_with_assimp(a, (dir / "l.glb").string(), "glb2", r);
  ImportedScene via_gltf = import_with_assimp((dir / "l.glb").string(), 64, true, r);
  write_course_xml(via_gltf, (dir / "g.xml").string(), r);
  write_course_xml({a, {}, {}}, (dir / "x.xml").string(), r);
  for (const char* back : {"g.xml", "x.xml"}) {
    const rt::SceneDesc b = rt::load_scene((dir / back).string());
    ASSERT_EQ(b.lights.size(), 2u) << back;
    for (size_t i = 0; i < 2; ++i) {
      const Light &la = a.lights[i], &lb = b.lights[i];
      EXPECT_EQ(la.type, lb.type) << back << " light " << i;
      EXPECT_EQ(std::memcmp(&la.position, &lb.position, sizeof la.position), 0) << back << i;
      EXPECT_EQ(std::memcmp(&la.normal, &lb.normal, sizeof la.normal), 0) << back << i;
      EXPECT_EQ(std::memcmp(&la.emission, &lb.emission, sizeof la.emission), 0) << back << i;
      EXPECT_EQ(RT_SPOT_COS_FALLOFF(&la), RT_SPOT_COS_FALLOFF(&lb)) << back << " light " << i;
      EXPECT_EQ(RT_SPOT_COS_COVERAGE(&la), RT_SPOT_COS_COVERAGE(&lb)) << back << " light " << i;
    }
  }
  fs::remove_all(dir);
}

TEST(ConvertExtras, OutOfRangeValuesAreRefusedNamingTheFileAndElement) {
  char tmpl[] = "/tmp/rtconvert_extras_XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const fs::path dir = tmpl;
  const std::string scene = std::string(RT_SHARED_SCENES_DIR) + "/hw4/wood_box_all.xml";
  if (!fs::exists(scene)) GTEST_SKIP() << scene << " is not present (../shared/scenes)";
  rt::SceneDesc a = rt::load_scene(scene);
  Report r;
  const std::string glb = (dir / "w.glb").string();
  export_with_assimp(a, glb, "glb2", r, course_image_files(scene, a));
  const json good = read_gltf_json(glb);
  for (const char* field : {"decal", "type", "image"}) {
    json g = good;
    g["scenes"][0]["extras"][kExtrasKey]["textures"][1][field] = 99;
    rewrite_glb_json(glb, g);
    try {
      import_with_assimp(glb, 64, true, r);
      ADD_FAILURE() << field << " 99 was accepted";
    } catch (const ConvertError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find(glb + ": extras.ceng795.textures[1]: a value is out of range"), 0u) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
  json g = good;
  g["materials"][0]["extras"][kExtrasKey]["brdf"] = 7;
  rewrite_glb_json(glb, g);
  EXPECT_THROW(import_with_assimp(glb, 64, true, r), ConvertError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtconvert
