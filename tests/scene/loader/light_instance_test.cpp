// MeshInstances of a LightMesh: each instance is a light of its own, sampled by area
// through its own transform, so an instance renders exactly as a second LightMesh with
// the same faces and transform would.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/errors.h"
#include "support/render_both.h"
#include "support/loader_fixture.h"

namespace rt::test {
namespace {

using LightInstances = LoaderTest;

// A white plane at z = -1 lit by a square LightMesh at x = -0.6 facing it (clockwise seen
// from +z, so it emits towards -z), and `more` objects.
std::string Scene(const std::string& more) {
  return R"(<Scene><Cameras><Camera id="1" type="lookAt"><Position>0 0 5</Position>
    <GazePoint>0 0 0</GazePoint><Up>0 1 0</Up><FovY>40</FovY><NearDistance>1</NearDistance>
    <ImageResolution>16 16</ImageResolution><NumSamples>4</NumSamples>
    <ImageName>out.png</ImageName></Camera></Cameras>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material>
    <Material id="2"><DiffuseReflectance>0 0 0</DiffuseReflectance></Material></Materials>
  <Transformations><Translation id="1">1.2 0 0</Translation>
    <Translation id="2">0 0 0.5</Translation></Transformations>
  <VertexData>-0.85 -0.25 0  -0.35 -0.25 0  -0.35 0.25 0  -0.85 0.25 0
    -3 -3 -1  3 -3 -1  3 3 -1  -3 3 -1</VertexData>
  <Objects>
    <Mesh id="1"><Material>1</Material><Faces>5 6 7 5 7 8</Faces></Mesh>
    <LightMesh id="2"><Material>2</Material><Radiance>40 40 40</Radiance>
      <Faces>1 3 2 1 4 3</Faces></LightMesh>)" +
         more + "</Objects></Scene>";
}

int MeshLights(const SceneDesc& scene) {
  FlatScene flat = prepare_scene(scene, RenderOptions{});
  prepare_camera(flat, scene, 0, RenderOptions{});
  int n = 0;
  for (const Light& l : flat.lights) n += l.type == RT_LIGHT_MESH;
  return n;
}

TEST_F(LightInstances, AnInstanceEmitsAsTheLightMeshItCopies) {
  SceneDesc instanced = load_scene(write("a.xml", Scene(R"(
    <MeshInstance id="3" baseMeshId="2"><Transformations>t1</Transformations></MeshInstance>)")));
  SceneDesc copied = load_scene(write("b.xml", Scene(R"(
    <LightMesh id="3"><Material>2</Material><Radiance>40 40 40</Radiance>
      <Faces>1 3 2 1 4 3</Faces><Transformations>t1</Transformations></LightMesh>)")));
  SceneDesc single = load_scene(write("c.xml", Scene("")));
  EXPECT_EQ(MeshLights(instanced), 2);
  EXPECT_EQ(MeshLights(single), 1);
  std::vector<float> a = RenderBoth(instanced), b = RenderBoth(copied), c = RenderBoth(single);
  EXPECT_EQ(DifferingValues(a, b), 0u);
  // The instance does light the plane: without it the image is darker.
  double sum_a = 0, sum_c = 0;
  for (size_t i = 0; i < a.size(); ++i) sum_a += a[i], sum_c += c[i];
  EXPECT_GT(sum_a, 1.5 * sum_c);
  EXPECT_GT(sum_c, 0);
}

// An instance of an instance of a light is a light too, with the composed transform.
TEST_F(LightInstances, ChainsEmit) {
  SceneDesc chain = load_scene(write("a.xml", Scene(R"(
    <MeshInstance id="3" baseMeshId="2"><Transformations>t1</Transformations></MeshInstance>
    <MeshInstance id="4" baseMeshId="3"><Transformations>t2</Transformations></MeshInstance>)")));
  EXPECT_EQ(MeshLights(chain), 3);
}

TEST_F(LightInstances, MovingInstancesAreRefused) {
  expect_error(
      write("a.xml", Scene(R"(
    <MeshInstance id="3" baseMeshId="2"><MotionBlur>1 0 0</MotionBlur></MeshInstance>)")),
      {"MeshInstance id=3 > MotionBlur", "instance of a LightMesh", "the light would not move"});
}

}  // namespace
}  // namespace rt::test
