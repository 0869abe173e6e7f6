// Objects in the loader (src/scene/loader/objects.cpp): vertex and face indices, spheres, mesh
// instances, PLY files referenced by a mesh, degenerate triangles and motion blur.
#include <gtest/gtest.h>

#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "support/loader_fixture.h"

namespace rt {
namespace {

using namespace test;

TEST_F(LoaderErrors, FaceIndexOutOfRange) {
  expect_error({{"1 3 4", "1 3 0"}}, {"Mesh id=1 > Faces", "vertex index 0", "[1, 8]"});
  expect_error({{"1 3 4", "1 9 4"}}, {"Mesh id=1 > Faces", "vertex index 9", "[1, 8]"});
  expect_error({{"1 3 4", "1 -3 4"}}, {"Mesh id=1 > Faces", "vertex index -3"});
  expect_error({{"5 6 7", "5 6 9"}}, {"Triangle id=1 > Indices", "vertex index 9"});
  // Huge values must not overflow an integer conversion into a bogus number.
  expect_error({{"1 3 4", "1 3 1e30"}}, {"Mesh id=1 > Faces", "1e+30"});
}

TEST_F(LoaderErrors, SphereCenterOutOfRange) {
  expect_error({{"<Center>8</Center>", "<Center>9</Center>"}},
               {"Sphere id=1 > Center", "vertex index 9", "[1, 8]"});
  expect_error({{"<Center>8</Center>", "<Center>0</Center>"}},
               {"Sphere id=1 > Center", "vertex index 0"});
  expect_error({{"<Center>8</Center>", "<Center>-3e38</Center>"}},
               {"Sphere id=1 > Center", "vertex index -3e+38"});
}

TEST_F(LoaderErrors, NonIntegerIndex) {
  expect_error({{"1 3 4", "1 3.5 4"}}, {"Mesh id=1 > Faces", "'3.5'", "not a whole number"});
  expect_error({{"1 3 4", "1 x 4"}}, {"Mesh id=1 > Faces", "'x'"});
  expect_error({{"<Center>8</Center>", "<Center>2.5</Center>"}}, {"Sphere id=1 > Center", "'2.5'"});
  expect_error({{"<Faces>", "<Faces vertexOffset=\"one\">"}},
               {"Mesh id=1 > Faces", "vertexOffset", "'one'"});
}

TEST_F(LoaderErrors, BaseMeshIdThatDoesNotExist) {
  expect_error({{"</Objects>", "<MeshInstance id=\"2\" baseMeshId=\"5\"/></Objects>"}},
               {"MeshInstance id=2", "'5'"});
  // A Triangle or Sphere id is no mesh.
  expect_error({{"</Objects>", "<MeshInstance id=\"2\" baseMeshId=\"\"/></Objects>"}},
               {"MeshInstance id=2", "''"});
  expect_error({{"</Objects>", "<MeshInstance id=\"2\"/></Objects>"}},
               {"MeshInstance id=2", "baseMeshId"});
  expect_error({{"</Objects>",
                 "<MeshInstance id=\"2\" baseMeshId=\"1\" resetTransform=\"yes\"/>"
                 "</Objects>"}},
               {"MeshInstance id=2", "resetTransform", "'yes'"});
}

TEST_F(LoaderErrors, NegativeRadius) {
  expect_error({{"<Radius>0.3</Radius>", "<Radius>-0.3</Radius>"}},
               {"Sphere id=1 > Radius", "'-0.3'"});
  expect_error({{"<Radius>0.3</Radius>", "<Radius>0</Radius>"}}, {"Sphere id=1 > Radius", "'0'"});
}

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n";

TEST_F(LoaderErrors, MissingPlyFileRelativeToXml) {
  std::string path = write("sub/scene.xml", tiny_scene_with_ply_mesh("meshes/m.ply"));
  std::string resolved = (dir_ / "sub" / "meshes" / "m.ply").string();
  // Named once, by where it was looked for.
  expect_error(path, {"Mesh id=1 > Faces", "plyFile '" + resolved + "': cannot open"});
  // Next to the XML, not next to the working directory, is where it is looked for.
  write("sub/meshes/m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 2\n");
  EXPECT_EQ(load_scene(path).meshes.at(0).triangles.size(), 1u);
}

TEST_F(LoaderErrors, TruncatedPly) {
  write("m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n");
  std::string path = write("scene.xml", tiny_scene_with_ply_mesh("m.ply"));
  expect_error(path, {"Mesh id=1 > Faces", (dir_ / "m.ply").string(), "vertex"});
  // A binary body cut short.
  std::string bin =
      replaced_all(kPlyHeader, "ascii", "binary_little_endian") + std::string(20, '\0');
  write("b.ply", bin);
  path = write("scene2.xml", tiny_scene_with_ply_mesh("b.ply"));
  expect_error(path, {"Mesh id=1 > Faces", (dir_ / "b.ply").string()});
}

TEST_F(LoaderErrors, PlyIndexOutOfRange) {
  write("m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 4\n");
  std::string path = write("scene.xml", tiny_scene_with_ply_mesh("m.ply"));
  expect_error(path, {"Mesh id=1 > Faces", "m.ply", "index 4", "out of range"});
}

TEST_F(LoaderErrors, PlyHugeFaceCountFailsFast) {
  std::string h = replaced_all(kPlyHeader, "element face 1", "element face 2000000000");
  write("m.ply", h + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 2\n");
  std::string path = write("scene.xml", tiny_scene_with_ply_mesh("m.ply"));
  expect_error(path, {"Mesh id=1 > Faces", "2000000000"});
}

TEST_F(LoaderAccepts, DegenerateTrianglesSkippedAndCounted) {
  // 1 1 2 repeats a vertex; 1 2 and (-0.5, -1.5, -2) are collinear with 1 and 2.
  SceneDesc s = load_scene(
      scene({{"-0.875 1 -2", "-0.5 -1.5 -2"}, {"1 3 4", "1 3 4\n 1 1 2\n 1 2 8\n 2 2 2"}}));
  EXPECT_EQ(s.degenerate_triangles, 3);
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].triangles.size(), 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("3 degenerate"), std::string::npos) << s.warnings[0];
}

TEST_F(LoaderAccepts, MotionBlur) {
  SceneDesc s = load_scene(
      scene({{"<Radius>0.3</Radius>", "<Radius>0.3</Radius><MotionBlur>0 0.5 -1</MotionBlur>"}}));
  EXPECT_EQ(s.objects.at(2).motion.y, 0.5);
  EXPECT_EQ(s.objects.at(2).motion.z, -1);
  EXPECT_EQ(s.objects.at(0).motion.z, 0);
}

TEST_F(LoaderAccepts, VertexOffsetOnFaces) {
  SceneDesc s = load_scene(scene({{"<Faces>", "<Faces vertexOffset=\"4\">"}, {"1 3 4", "2 1 3"}}));
  const MeshDesc& m = s.meshes.at(0);
  ASSERT_EQ(m.triangles.size(), 2u);
  // "3 1 2" + 4 -> vertices 7, 5, 6.
  Vec3d p = m.positions.at(m.triangles[0][0]);
  EXPECT_EQ(p.x, 0.875);
  EXPECT_EQ(p.y, 1);
}

TEST_F(LoaderAccepts, PlyQuadsTriangulated) {
  std::string h = replaced_all(kPlyHeader, "element face 1", "element face 2");
  write("m.ply", h + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n4 0 1 2 3\n3 0 2 3\n");
  SceneDesc s = load_scene(write("scene.xml", tiny_scene_with_ply_mesh("m.ply")));
  EXPECT_EQ(s.meshes.at(0).triangles.size(), 3u);
  EXPECT_EQ(s.meshes.at(0).positions.size(), 4u);
}

}  // namespace
}  // namespace rt
