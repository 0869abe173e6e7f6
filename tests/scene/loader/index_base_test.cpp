// <ZeroBasedIndexing> (hw6/sponza.xml): indices into VertexData and TexCoordData count
// from 0; PLY files, always 0-based, are unaffected; out-of-range indices are reported in
// the file's own base.
#include <gtest/gtest.h>

#include "util/errors.h"
#include "support/render_both.h"
#include "support/loader_fixture.h"

namespace rt::test {
namespace {

// kTinyScene rewritten 0-based: every index one lower, the flag set.
const Edits kZeroBased = {
    {"<Cameras>", "<ZeroBasedIndexing>true</ZeroBasedIndexing>\n    <Cameras>"},
    {"3 1 2\n                1 3 4", "2 0 1\n                0 2 3"},
    {"5 6 7", "4 5 6"},
    {"<Center>8</Center>", "<Center>7</Center>"},
};

TEST_F(LoaderAccepts, ZeroBasedIndexingGivesTheOneBasedSceneByteForByte) {
  SceneDesc one = load_scene(scene({}));
  SceneDesc zero = load_scene(write("zero.xml", edited(kTinyScene, kZeroBased)));
  ASSERT_EQ(one.meshes.size(), zero.meshes.size());
  for (size_t m = 0; m < one.meshes.size(); ++m) {
    EXPECT_EQ(one.meshes[m].triangles, zero.meshes[m].triangles);
    ASSERT_EQ(one.meshes[m].positions.size(), zero.meshes[m].positions.size());
    for (size_t v = 0; v < one.meshes[m].positions.size(); ++v)
      EXPECT_EQ(length(one.meshes[m].positions[v] - zero.meshes[m].positions[v]), 0.0);
  }
  ExpectSameLitImage(RenderBoth(one), RenderBoth(zero));
}

TEST_F(LoaderAccepts, ZeroBasedIndexingFalseIsOneBased) {
  SceneDesc one = load_scene(scene({}));
  SceneDesc flag = load_scene(
      scene({{"<Cameras>", "<ZeroBasedIndexing> false </ZeroBasedIndexing>\n    <Cameras>"}}));
  EXPECT_EQ(one.meshes[0].triangles, flag.meshes[0].triangles);
}

// PLY indices address the PLY's own vertices from 0 whatever the scene's base.
TEST_F(LoaderAccepts, ZeroBasedIndexingLeavesPlyMeshesAlone) {
  write("quad.ply",
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
        "end_header\n-0.5 0.5 -2\n-0.5 -0.5 -2\n0.5 -0.5 -2\n0.5 0.5 -2\n3 2 0 1\n3 0 2 3\n");
  std::string one_based = tiny_scene_with_ply_mesh("quad.ply");
  SceneDesc a = load_scene(write("one.xml", one_based));
  Edits zero(kZeroBased.begin(), kZeroBased.end());
  zero.erase(zero.begin() + 1);  // The inline faces are gone.
  SceneDesc b = load_scene(write("zero.xml", edited(one_based, zero)));
  EXPECT_EQ(a.meshes[0].triangles, b.meshes[0].triangles);
  EXPECT_EQ(DifferingValues(RenderBoth(a), RenderBoth(b)), 0u);
}

TEST_F(LoaderErrors, ZeroBasedIndexOutOfRangeIsNamedInItsBase) {
  Edits e = kZeroBased;
  e[1].second = "2 0 1\n                0 2 8";
  expect_error(e, {"Mesh id=1 > Faces", "vertex index 8 out of range [0, 7]", "ZeroBasedIndexing"});
  e = kZeroBased;
  e[1].second = "2 0 1\n                0 2 -1";
  expect_error(e, {"Faces", "vertex index -1 out of range [0, 7]"});
  e = kZeroBased;
  e[3].second = "<Center>8</Center>";
  expect_error(e, {"Sphere id=1 > Center", "vertex index 8 out of range [0, 7]"});
  // The 1-based message is unchanged.
  expect_error({{"3 1 2", "3 0 2"}}, {"Faces", "vertex index 0 out of range [1, 8]"});
}

TEST_F(LoaderErrors, ZeroBasedIndexingMustBeTrueOrFalse) {
  expect_error({{"<Cameras>", "<ZeroBasedIndexing>yes</ZeroBasedIndexing><Cameras>"}},
               {"ZeroBasedIndexing", "'yes' is neither true nor false"});
}

}  // namespace
}  // namespace rt::test
