// Directional and spot lights through rtconvert's glTF extras and its XML writer: the
// device values the loader made (unit direction, cosines of the half cone angles) come
// back with the same bits, so the renders are identical.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "convert.h"

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
      EXPECT_EQ(la.param0, lb.param0) << back << " light " << i;
      EXPECT_EQ(la.param1, lb.param1) << back << " light " << i;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtconvert
