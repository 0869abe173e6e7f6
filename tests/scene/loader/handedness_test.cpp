// Camera handedness="left" (hw5/head_env_light.xml, a scene ported from pbrt): the right
// vector is reversed, so the image is the right-handed one mirrored left to right.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/render_both.h"
#include "support/loader_fixture.h"

namespace rt::test {
namespace {

using LoaderHandedness = LoaderTest;

// The tiny scene is asymmetric (a triangle and a sphere on the right, top) and renders
// one sample per pixel with point and ambient light only, so its image is exact: at a
// width of 16 over the film [-1, 1] every film coordinate and its mirror image are exact
// floats, and the left-handed camera's rays are the right-handed ones bit for bit.
TEST_F(LoaderHandedness, LeftIsTheRightHandedImageMirrored) {
  SceneDesc right =
      load_scene(scene({{"<Camera id=\"1\">", "<Camera id=\"1\" handedness=\"right\">"}}));
  SceneDesc left =
      load_scene(scene({{"<Camera id=\"1\">", "<Camera id=\"1\" handedness=\"left\">"}}));
  EXPECT_FALSE(right.cameras[0].left_handed);
  EXPECT_TRUE(left.cameras[0].left_handed);
  const int w = right.cameras[0].width, h = right.cameras[0].height;
  std::vector<float> r = RenderBoth(right), l = RenderBoth(left);
  ASSERT_EQ(r.size(), static_cast<size_t>(w * h * 3));
  std::vector<float> mirrored(r.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) mirrored[(y * w + x) * 3 + c] = r[(y * w + (w - 1 - x)) * 3 + c];
  EXPECT_EQ(DifferingValues(l, mirrored), 0u);
  // The scene is not symmetric, so the test can fail: the mirror differs from the original.
  EXPECT_GT(DifferingValues(r, mirrored), 0u);
}

TEST_F(LoaderHandedness, OtherValuesAreErrors) {
  expect_error({{"<Camera id=\"1\">", "<Camera id=\"1\" handedness=\"up\">"}},
               {"Camera id=1", "handedness 'up' is neither left nor right"});
}

}  // namespace
}  // namespace rt::test
