// Texture input: the PNG/JPEG reader and the loader's Textures, TexCoordData and object
// texture lists, including every bad input ending in one clear line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "util/errors.h"
#include "image/read_ldr.h"
#include "io/png_io.h"
#include "scene/scene.h"
#include "support/test_scene.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// A quad with texture coordinates and a sphere, each listing texture 1.
const char* kTextured = R"(<Scene>
  <Cameras><Camera id="1" type="lookAt">
    <Position>0 0 5</Position><GazePoint>0 0 0</GazePoint><Up>0 1 0</Up><FovY>40</FovY>
    <NearDistance>1</NearDistance><ImageResolution>8 8</ImageResolution>
    <ImageName>t.png</ImageName></Camera></Cameras>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material></Materials>
  <Textures>
    <Images><Image id="1">tex.png</Image></Images>
    <TextureMap id="1" type="image"><ImageId>1</ImageId><DecalMode>replace_kd</DecalMode>
      <Interpolation>bilinear</Interpolation></TextureMap>
    <TextureMap id="2" type="perlin"><DecalMode>bump_normal</DecalMode><NoiseScale>3</NoiseScale>
      <NoiseConversion>absval</NoiseConversion><BumpFactor>0.5</BumpFactor></TextureMap>
    <TextureMap id="3" type="checkerboard"><DecalMode>blend_kd</DecalMode><Scale>4</Scale>
      <Offset>0.5</Offset><BlackColor>0.1 0.2 0.3</BlackColor><WhiteColor>1 1 1</WhiteColor></TextureMap>
  </Textures>
  <VertexData>-1 -1 0  1 -1 0  1 1 0  -1 1 0  0 0 -3</VertexData>
  <TexCoordData>0 1  1 1  1 0  0 0  0.5 0.5</TexCoordData>
  <Objects>
    <Mesh id="1"><Material>1</Material><Textures>1 2</Textures><Faces>1 2 3 1 3 4</Faces></Mesh>
    <Sphere id="1"><Material>1</Material><Textures>3</Textures><Center>5</Center>
      <Radius>0.5</Radius></Sphere>
  </Objects>
</Scene>
)";

class TextureLoader : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    Image8 img;
    img.width = 2;
    img.height = 1;
    img.rgb = {10, 20, 30, 200, 210, 220};
    write_png((dir_ / "tex.png").string(), img);
  }

  // The template with `from` replaced by `to` (which must occur once), written out.
  std::string scene(const std::string& from = "", const std::string& to = "") {
    return write("scene.xml",
                 from.empty() ? std::string(kTextured) : test::replaced(kTextured, from, to));
  }

  void expect_error(const std::string& from, const std::string& to,
                    std::initializer_list<std::string> parts) {
    test::expect_load_error(scene(from, to), parts);
  }
};

TEST_F(TextureLoader, ReadsEveryElement) {
  SceneDesc s = load_scene(scene());
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.images[0].width, 2);
  EXPECT_EQ(s.images[0].at(1, 0, 2), 220.0f);
  ASSERT_EQ(s.textures.size(), 3u);
  const TextureDesc& img = s.textures[0].desc;
  EXPECT_EQ(img.type, RT_TEXTURE_IMAGE);
  EXPECT_EQ(img.decal, RT_DECAL_REPLACE_KD);
  EXPECT_EQ(img.interpolation, RT_INTERP_BILINEAR);
  EXPECT_EQ(img.normalizer, 255.0f);  // The default.
  const TextureDesc& perlin = s.textures[1].desc;
  EXPECT_EQ(perlin.type, RT_TEXTURE_PERLIN);
  EXPECT_EQ(perlin.decal, RT_DECAL_BUMP_NORMAL);
  EXPECT_EQ(perlin.noise_scale, 3.0f);
  EXPECT_EQ(perlin.noise_conversion, RT_NOISE_ABSVAL);
  EXPECT_EQ(perlin.bump_factor, 0.5f);
  const TextureDesc& checker = s.textures[2].desc;
  EXPECT_EQ(checker.checker_scale, 4.0f);
  EXPECT_EQ(checker.checker_offset, 0.5f);
  EXPECT_EQ(checker.black.z, 0.3f);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].textures, (std::vector<int>{0, 1}));
  EXPECT_EQ(s.objects[1].textures, (std::vector<int>{2}));
  // Texture coordinates follow the vertices: vertex 3 is (1, 1, 0) with uv (1, 0).
  const MeshDesc& m = s.meshes[s.objects[0].mesh];
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (m.positions[i].x == 1 && m.positions[i].y == 1) {
      EXPECT_EQ(m.uvs[i][0], 1.0);
      EXPECT_EQ(m.uvs[i][1], 0.0);
    }
}

TEST_F(TextureLoader, TextureOffsetShiftsTheCoordinateIndices) {
  SceneDesc s = load_scene(
      scene("<Faces>1 2 3 1 3 4</Faces>", "<Faces textureOffset=\"1\">1 2 3 1 3 4</Faces>"));
  const MeshDesc& m = s.meshes[s.objects[0].mesh];
  // Vertex 1 now takes coordinate 2: (1, 1).
  EXPECT_EQ(m.uvs[0][0], 1.0);
  EXPECT_EQ(m.uvs[0][1], 1.0);
}

TEST_F(TextureLoader, BackgroundTexture) {
  SceneDesc s = load_scene(
      scene("<DecalMode>replace_kd</DecalMode>", "<DecalMode>replace_background</DecalMode>"));
  EXPECT_EQ(s.background_texture, 0);
  EXPECT_EQ(s.objects[0].textures, (std::vector<int>{1}));  // Not a surface texture.
}

TEST_F(TextureLoader, BadInputsGiveOneLine) {
  expect_error("<Image id=\"1\">tex.png</Image>", "<Image id=\"1\">missing.png</Image>",
               {"ImageId", "missing.png", "cannot read image"});
  expect_error("<Image id=\"1\">tex.png</Image>", "<Image id=\"1\">scene.xml</Image>",
               {"scene.xml", "neither PNG nor JPEG"});
  expect_error("<ImageId>1</ImageId>", "<ImageId>7</ImageId>", {"no Image with id '7'"});
  expect_error("<Textures>1 2</Textures>", "<Textures>1 9</Textures>",
               {"Mesh id=1", "no TextureMap with id '9'"});
  expect_error("<DecalMode>replace_kd</DecalMode>", "<DecalMode>replace_kdd</DecalMode>",
               {"DecalMode", "replace_kdd"});
  expect_error("<Interpolation>bilinear</Interpolation>", "<Interpolation>cubic</Interpolation>",
               {"Interpolation", "cubic"});
  expect_error("type=\"perlin\"", "type=\"marble\"", {"marble"});
  expect_error("<NoiseScale>3</NoiseScale>", "<NoiseScale>0</NoiseScale>",
               {"NoiseScale", "must be positive"});
  expect_error("<TexCoordData>0 1  1 1  1 0  0 0  0.5 0.5</TexCoordData>",
               "<TexCoordData>0 1  1 1</TexCoordData>",
               {"Faces", "texture coordinate index 3", "out of range [1, 2]"});
  expect_error("<TexCoordData>0 1  1 1  1 0  0 0  0.5 0.5</TexCoordData>",
               "<TexCoordData>0 1  1 1  1 0  0 0  0.5</TexCoordData>",
               {"TexCoordData", "multiple of 2"});
  expect_error("<TexCoordData>0 1  1 1  1 0  0 0  0.5 0.5</TexCoordData>", "",
               {"Mesh id=1", "no texture coordinates"});
  expect_error("<Textures>1 2</Textures>", "<Textures>1 2 3 2 1</Textures>",
               {"more than 4 textures"});
}

TEST(ReadLdr, PngAndJpeg) {
  fs::path dir = fs::temp_directory_path() / ("rt_read_ldr_" + std::to_string(getpid()));
  fs::create_directories(dir);
  Image8 img;
  img.width = 1;
  img.height = 2;
  img.rgb = {1, 2, 3, 250, 251, 252};
  write_png((dir / "a.png").string(), img);
  ImageF f = read_ldr((dir / "a.png").string());
  EXPECT_EQ(f.width, 1);
  EXPECT_EQ(f.height, 2);
  EXPECT_EQ(f.at(0, 1, 0), 250.0f);
  // A truncated JPEG: one line naming the file.
  std::ofstream(dir / "bad.jpg", std::ios::binary) << "\xff\xd8\xff\xe0 truncated";
  try {
    read_ldr((dir / "bad.jpg").string());
    ADD_FAILURE() << "read a broken JPEG";
  } catch (const std::runtime_error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("bad.jpg: cannot read image: JPEG"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  fs::remove_all(dir);
  const std::string earth = std::string(RT_SHARED_SCENES_DIR) + "/hw4/textures/earth.jpg";
  if (!fs::exists(earth)) GTEST_SKIP() << earth << " is not present (../shared/scenes)";
  ImageF e = read_ldr(earth);
  EXPECT_EQ(e.width, 1024);
  EXPECT_EQ(e.height, 512);
  EXPECT_EQ(e.pixels.size(), 1024u * 512u * 3u);
}

}  // namespace
}  // namespace rt
