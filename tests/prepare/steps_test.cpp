// The two steps of the preparation (src/prepare/flat_scene.h): prepare_camera depends on
// the camera alone, not on the cameras prepared before it, and the memory check's estimate
// of a camera's arrays (camera_array_counts) covers what prepare_camera then makes.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "device/cpu/cpu_device.h"
#include "scene/scene.h"
#include "support/device_harness.h"
#include "support/test_scene.h"

namespace rt {
namespace {

// kTinyScene with two more cameras far from the first (each its own frame), an area light,
// an emitting sphere and an emitting mesh, so that the frame moves instances and lights.
SceneDesc three_camera_scene() {
  const std::string cameras =
      R"(<Camera id="2"><Position>300 -20 7</Position><Gaze>-1 0 -0.1</Gaze><Up>0 1 0</Up>
           <NearPlane>-1 1 -0.5 0.5</NearPlane><NearDistance>1</NearDistance>
           <ImageResolution>12 6</ImageResolution><ImageName>b.png</ImageName></Camera>
         <Camera id="3"><Position>-5 40 2</Position><Gaze>0 -1 -0.2</Gaze><Up>0 0 1</Up>
           <NearPlane>-1 1 -0.5 0.5</NearPlane><NearDistance>1</NearDistance>
           <ImageResolution>10 20</ImageResolution><ImageName>c.png</ImageName></Camera>
      </Cameras>)";
  const std::string xml = test::edited(
      test::kTinyScene,
      {{"</Cameras>", cameras},
       {"</Lights>", R"(<AreaLight id="1"><Position>0 2 -2</Position><Normal>0 -1 0</Normal>
           <Size>1</Size><Radiance>5 5 5</Radiance></AreaLight></Lights>)"},
       {"</Objects>", R"(<LightSphere id="2"><Material>1</Material><Center>7</Center>
           <Radius>0.2</Radius><Radiance>3 3 3</Radiance></LightSphere>
         <LightMesh id="3"><Material>1</Material><Faces>3 1 2</Faces>
           <Radiance>1 1 1</Radiance></LightMesh></Objects>)"}});
  return load_scene_text(xml, "three.xml");
}

#define RT_EXPECT_SAME_ARRAY(Type, name)            \
  EXPECT_EQ(a.name.size(), b.name.size()) << #name; \
  if (a.name.size() == b.name.size())               \
    EXPECT_EQ(std::memcmp(a.name.data(), b.name.data(), sizeof(Type) * a.name.size()), 0) << #name;

void expect_same_arrays(const FlatScene& a, const FlatScene& b) {
  EXPECT_EQ(std::memcmp(&a.header, &b.header, sizeof a.header), 0);
  RT_DATA_ARRAYS(RT_EXPECT_SAME_ARRAY)
}
#undef RT_EXPECT_SAME_ARRAY

TEST(PrepareSteps, ACameraPreparesTheSameAfterOtherCameras) {
  const SceneDesc scene = three_camera_scene();
  ASSERT_EQ(scene.cameras.size(), 3u);
  CpuDevice device(1);
  for (int c = 0; c < 3; ++c) {
    SCOPED_TRACE(c);
    const PreparedScene fresh = test::prepare_on(device, scene, c, RenderOptions());
    std::string notice;
    PreparedScene reused = prepare_for_device(scene, RenderOptions(), device, &notice);
    for (int other = 0; other < 3; ++other) prepare_camera(reused, scene, (c + 1 + other) % 3);
    expect_same_arrays(fresh.flat, reused.flat);
    EXPECT_EQ(fresh.flat.stats.top_levels_built, 1);
    EXPECT_EQ(reused.flat.stats.top_levels_built, 3);
  }
}

TEST(PrepareSteps, TheMemoryEstimateCoversEveryCamerasArrays) {
  const SceneDesc scene = three_camera_scene();
  CpuDevice device(1);
  std::string notice;
  PreparedScene prepared = prepare_for_device(scene, RenderOptions(), device, &notice);
  const ArrayCounts estimate = camera_array_counts(prepared.flat, scene, prepared.options);
  for (int c = 0; c < 3; ++c) {
    SCOPED_TRACE(c);
    prepare_camera(prepared, scene, c);
    const ArrayCounts placed = array_counts(prepared.flat);
    // The top level's nodes vary with the camera; every other array's size does not.
#define RT_EXPECT_COUNT(Type, name)                 \
  if (std::string(#name) == "nodes")                \
    EXPECT_GE(estimate.name, placed.name) << #name; \
  else                                              \
    EXPECT_EQ(estimate.name, placed.name) << #name;
    RT_DATA_ARRAYS(RT_EXPECT_COUNT)
#undef RT_EXPECT_COUNT
  }
  EXPECT_EQ(estimate.lights, 4u);     // The point and area lights, the sphere and the mesh.
  EXPECT_EQ(estimate.light_cdf, 1u);  // The mesh light's one triangle.
}

// The lights that draw random numbers are numbered once, in the array's order: the area
// light first, then the object lights.
TEST(PrepareSteps, LightsAreNumberedInTheirOrder) {
  const SceneDesc scene = three_camera_scene();
  CpuDevice device(1);
  const PreparedScene p = test::prepare_on(device, scene, 1, RenderOptions());
  ASSERT_EQ(p.flat.header.num_lights, 4);
  EXPECT_EQ(p.flat.lights[0].type, RT_LIGHT_POINT);
  EXPECT_EQ(p.flat.lights[1].type, RT_LIGHT_AREA);
  EXPECT_EQ(p.flat.lights[1].sample_index, 0);
  EXPECT_EQ(p.flat.lights[2].type, RT_LIGHT_SPHERE);
  EXPECT_EQ(p.flat.lights[2].sample_index, 1);
  EXPECT_EQ(p.flat.lights[3].type, RT_LIGHT_MESH);
  EXPECT_EQ(p.flat.lights[3].sample_index, 2);
  EXPECT_TRUE(p.flat.header.features & RT_LIGHT_SPHERE);
  EXPECT_TRUE(p.flat.header.features & RT_LIGHT_MESH);
  EXPECT_TRUE(p.flat.header.features & RT_FEATURE_SPHERES);
  EXPECT_TRUE(p.flat.header.features & RT_FEATURE_TRIANGLES);
}

}  // namespace
}  // namespace rt
