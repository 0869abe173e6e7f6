// binaryFile on VertexData, TexCoordData and Faces (hw6/sponza.xml; layout in
// src/scene/loader/binary_data.h): small files written here give the geometry, texture
// coordinates and image of the inline text they encode, and bad files one clear line.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "util/errors.h"
#include "support/render_both.h"
#include "support/loader_fixture.h"

namespace rt::test {
namespace {

// The file bytes: the count, then the values, little-endian 4-byte words.
template <class T>
std::string Records(int32_t count, const std::vector<T>& values) {
  static_assert(sizeof(T) == 4, "4-byte values");
  std::string out;
  auto put = [&out](uint32_t w) {
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((w >> (8 * b)) & 255u));
  };
  put(static_cast<uint32_t>(count));
  for (T v : values) {
    uint32_t w;
    std::memcpy(&w, &v, 4);
    put(w);
  }
  return out;
}

// kTinyScene's eight vertices and its mesh's two triangles (1-based, as written inline).
const std::vector<float> kVertices = {-0.5f, 0.5f, -2,     -0.5f, -0.5f, -2,      0.5f, -0.5f,
                                      -2,    0.5f, 0.5f,   -2,    0.75f, 0.75f,   -2,   1,
                                      0.75f, -2,   0.875f, 1,     -2,    -0.875f, 1,    -2};
const std::vector<int32_t> kFaces = {3, 1, 2, 1, 3, 4};

// An element of kTinyScene as written there, from `open` through `close`.
std::string Written(const std::string& open, const std::string& close) {
  const std::string scene = kTinyScene;
  const size_t from = scene.find(open), to = scene.find(close, from) + close.size();
  return scene.substr(from, to - from);
}

class BinaryData : public LoaderTest {
 protected:
  // kTinyScene with its VertexData and its mesh's Faces read from vertices.bin and
  // faces.bin, plus `edits`.
  std::string binary_scene(const Edits& edits = {}) {
    Edits all = {{Written("<VertexData>", "</VertexData>"),
                  R"(<VertexData binaryFile="geo/vertices.bin"/>)"},
                 {Written("<Faces>", "</Faces>"), R"(<Faces binaryFile="geo/faces.bin"/>)"}};
    all.insert(all.end(), edits.begin(), edits.end());
    return scene(all);
  }
};

TEST_F(BinaryData, GivesTheInlineSceneByteForByte) {
  write("geo/vertices.bin", Records(8, kVertices));
  write("geo/faces.bin", Records(2, kFaces));
  SceneDesc text = load_scene(scene({}));
  SceneDesc binary = load_scene(binary_scene());
  EXPECT_EQ(text.meshes[0].triangles, binary.meshes[0].triangles);
  ExpectSameLitImage(RenderBoth(text), RenderBoth(binary));
}

// As sponza.xml: binary faces with ZeroBasedIndexing hold 0-based indices.
TEST_F(BinaryData, FacesFollowZeroBasedIndexing) {
  write("geo/vertices.bin", Records(8, kVertices));
  write("geo/faces.bin", Records(2, std::vector<int32_t>{2, 0, 1, 0, 2, 3}));
  SceneDesc text = load_scene(scene({}));
  SceneDesc binary = load_scene(
      binary_scene({{"<Cameras>", "<ZeroBasedIndexing>true</ZeroBasedIndexing><Cameras>"},
                    {"5 6 7", "4 5 6"},
                    {"<Center>8</Center>", "<Center>7</Center>"}}));
  EXPECT_EQ(text.meshes[0].triangles, binary.meshes[0].triangles);
  EXPECT_EQ(DifferingValues(RenderBoth(text), RenderBoth(binary)), 0u);
}

TEST_F(BinaryData, TexCoordDataFromAFile) {
  write("geo/vertices.bin", Records(8, kVertices));
  write("geo/faces.bin", Records(2, kFaces));
  std::vector<float> uv(16);
  for (size_t i = 0; i < uv.size(); ++i) uv[i] = 0.0625f * static_cast<float>(i);
  write("geo/uv.bin", Records(8, uv));
  std::string inline_uv = "<TexCoordData>";
  for (float v : uv) inline_uv += " " + std::to_string(v);
  inline_uv += "</TexCoordData>\n    <Objects>";
  // A checkerboard needs no image but makes the mesh read its texture coordinates.
  const Edits textured = {{"<Objects>", R"(<Textures><TextureMap id="1" type="checkerboard">
        <DecalMode>replace_kd</DecalMode></TextureMap></Textures>
    <Objects>)"},
                          {"<Faces", "<Textures>1</Textures><Faces"}};
  Edits text_edits = textured;
  text_edits[0].second = replaced(text_edits[0].second, "<Objects>", inline_uv);
  Edits binary_edits = textured;
  binary_edits[0].second = replaced(binary_edits[0].second, "<Objects>",
                                    "<TexCoordData binaryFile=\"geo/uv.bin\"/><Objects>");
  SceneDesc text = load_scene(scene(text_edits));
  SceneDesc binary = load_scene(binary_scene(binary_edits));
  ASSERT_EQ(text.meshes[0].uvs.size(), 4u);
  EXPECT_EQ(text.meshes[0].uvs, binary.meshes[0].uvs);
  EXPECT_EQ(DifferingValues(RenderBoth(text), RenderBoth(binary)), 0u);
}

TEST_F(BinaryData, BadFilesAreOneLine) {
  write("geo/faces.bin", Records(2, kFaces));
  // Missing.
  expect_error(binary_scene(), {"VertexData", "binaryFile '", "geo/vertices.bin': cannot open"});
  // Truncated: the count says 8 vertices, the file holds 7.
  write("geo/vertices.bin", Records(8, std::vector<float>(kVertices.begin(), kVertices.end() - 3)));
  expect_error(binary_scene(), {"VertexData", "vertices.bin", "truncated",
                                "8 records of 3 values (100 bytes)", "88 bytes"});
  // Count mismatch: more bytes than the count says.
  write("geo/vertices.bin", Records(7, kVertices));
  expect_error(binary_scene(),
               {"VertexData", "count mismatch", "7 records of 3 values (88 bytes)", "100 bytes"});
  // Shorter than the count itself, and a negative count.
  write("geo/vertices.bin", "ab");
  expect_error(binary_scene(), {"VertexData", "truncated: 2 bytes"});
  write("geo/vertices.bin", Records(-1, std::vector<float>{}));
  expect_error(binary_scene(), {"VertexData", "record count -1 is negative"});
  // A value that is no number.
  std::vector<float> nan = kVertices;
  nan[4] = std::nanf("");
  write("geo/vertices.bin", Records(8, nan));
  expect_error(binary_scene(), {"VertexData", "vertex 1 holds nan", "not a finite number"});
  // Faces: out of range (named in the scene's base), empty, both sources.
  write("geo/vertices.bin", Records(8, kVertices));
  write("geo/faces.bin", Records(2, std::vector<int32_t>{3, 1, 2, 1, 3, 9}));
  expect_error(binary_scene(), {"Mesh id=1 > Faces", "vertex index 9 out of range [1, 8]"});
  write("geo/faces.bin", Records(0, std::vector<int32_t>{}));
  expect_error(binary_scene(), {"Faces", "binaryFile 'geo/faces.bin' holds no triangle"});
  expect_error(scene({{"<Faces>", R"(<Faces binaryFile="geo/faces.bin">)"}}),
               {"Faces", "both a binaryFile and inline numbers"});
  expect_error(scene({{"<Faces>", R"(<Faces binaryFile="a.bin" plyFile="b.ply">)"}}),
               {"Faces", "both plyFile and binaryFile"});
}

}  // namespace
}  // namespace rt::test
