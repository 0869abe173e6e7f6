// Transformations in the loader: composite matrices, the order of a listed chain, singular
// transforms, unknown references, and mesh instances that inherit or reset transforms.
#include <gtest/gtest.h>

#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "support/loader_fixture.h"

namespace rt {
namespace {

using namespace test;

TEST_F(LoaderErrors, SingularComposedTransform) {
  // Each factor is fine; radius^3 underflows to a zero determinant.
  expect_error({{"<Radius>0.3</Radius>", "<Radius>1e-120</Radius>"}}, {"Sphere id=1", "singular"});
}

TEST_F(LoaderErrors, UnknownTransformationReference) {
  expect_error({{"<Objects>",
                 "<Transformations><Translation id=\"1\">1 0 0</Translation>"
                 "</Transformations><Objects>"},
                {"<Material>1</Material>\n            <Faces>",
                 "<Material>1</Material><Transformations>t1 t9</Transformations><Faces>"}},
               {"Mesh id=1 > Transformations", "'t9'"});
}

TEST_F(LoaderErrors, SingularTransform) {
  expect_error({{"<Objects>",
                 "<Transformations><Scaling id=\"1\">0 1 1</Scaling>"
                 "</Transformations><Objects>"}},
               {"Scaling id=1", "'0 1 1'", "singular"});
  expect_error({{"<Objects>",
                 "<Transformations><Rotation id=\"1\">45 0 0 0</Rotation>"
                 "</Transformations><Objects>"}},
               {"Rotation id=1", "'45 0 0 0'", "axis"});
  expect_error(
      {{"<Objects>",
        "<Transformations><Composite id=\"1\">0 0 0 0  0 1 0 0  0 0 1 0  "
        "0 0 0 1</Composite></Transformations><Objects>"},
       {"<Radius>0.3</Radius>", "<Radius>0.3</Radius><Transformations>c1</Transformations>"}},
      {"Sphere id=1 > Transformations", "'c1'", "singular"});
  expect_error({{"<Objects>",
                 "<Transformations><Composite id=\"1\">1 0 0 0  0 1 0 0  0 0 1 0  "
                 "0 0 1 0</Composite></Transformations><Objects>"}},
               {"Composite id=1", "'0 0 1 0'"});
}

const char* kTransforms = R"(<Transformations>
        <Translation id="1">1 0 0</Translation>
        <Translation id="2">0 2 0</Translation>
        <Scaling id="1">2 2 2</Scaling>
        <Rotation id="1">90 0 0 1</Rotation>
        <Composite id="1">1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1</Composite>
    </Transformations>
    <Objects>)";

void expect_point(const Mat4& m, Vec3d p, Vec3d want) {
  Vec3d q = m.point(p);
  EXPECT_NEAR(q.x, want.x, 1e-12);
  EXPECT_NEAR(q.y, want.y, 1e-12);
  EXPECT_NEAR(q.z, want.z, 1e-12);
}

TEST_F(LoaderTransforms, CompositeMatrixIsRowMajor) {
  SceneDesc s = load_scene(
      scene({{"<Objects>", kTransforms},
             {"<Radius>0.3</Radius>", "<Radius>1</Radius><Transformations>c1</Transformations>"},
             {"<Center>8</Center>", "<Center>1</Center>"}}));
  // Centre vertex 1 is (-0.5, 0.5, -2).
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {4.5, 6.5, 5});
}

TEST_F(LoaderTransforms, ListedOrderIsApplicationOrder) {
  // "t1 r1": translate by +x, then rotate 90 degrees about z: the origin ends at (0, 1, 0).
  std::string path = scene(
      {{"<Objects>", kTransforms},
       {"-0.875 1 -2", "0 0 0"},
       {"<Radius>0.3</Radius>", "<Radius>0.5</Radius><Transformations>t1 r1</Transformations>"}});
  SceneDesc s = load_scene(path);
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {0, 1, 0});
  expect_point(s.objects.at(2).transform, {1, 0, 0}, {0, 1.5, 0});  // radius 0.5 scales first
  s = load_scene(write(
      "r.xml",
      edited(kTinyScene, {{"<Objects>", kTransforms},
                          {"-0.875 1 -2", "0 0 0"},
                          {"<Radius>0.3</Radius>",
                           "<Radius>0.5</Radius><Transformations>r1 t1</Transformations>"}})));
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {1, 0, 0});
}

TEST_F(LoaderTransforms, MeshInstanceChain) {
  std::string path =
      scene({{"<Objects>", kTransforms},
             {"<Material>1</Material>\n            <Faces>",
              "<Material>1</Material><Transformations>t1</Transformations><Faces>"},
             {"</Objects>", R"(<MeshInstance id="2" baseMeshId="1" resetTransform="false">
            <Transformations>t2</Transformations></MeshInstance>
        <MeshInstance id="3" baseMeshId="2"><Transformations>r1</Transformations></MeshInstance>
        <MeshInstance id="4" baseMeshId="3" resetTransform="true">
            <Transformations>s1</Transformations></MeshInstance>
        <MeshInstance id="5" baseMeshId="4" resetTransform="false"></MeshInstance>
    </Objects>)"}});
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 7u);
  for (size_t i = 3; i < 7; ++i) EXPECT_EQ(s.objects[i].mesh, s.objects[0].mesh) << i;
  expect_point(s.objects[0].transform, {0, 0, 0}, {1, 0, 0});  // t1
  expect_point(s.objects[3].transform, {0, 0, 0}, {1, 2, 0});  // t2 after t1
  expect_point(s.objects[4].transform, {0, 0, 0},
               {-2, 1, 0});                                    // r1 after t2 t1 (default: no reset)
  expect_point(s.objects[5].transform, {1, 0, 0}, {2, 0, 0});  // reset: s1 alone
  expect_point(s.objects[6].transform, {1, 0, 0}, {2, 0, 0});  // identity after s1
}

TEST_F(LoaderTransforms, InstanceIdsReusingMeshIds) {
  // Older files number instances from 1 as well; baseMeshId="1" still means Mesh 1.
  std::string path =
      scene({{"<Objects>", kTransforms},
             {"<Material>1</Material>\n            <Faces>",
              "<Material>1</Material><Transformations>t1</Transformations><Faces>"},
             {"</Objects>", R"(<Mesh id="2"><Material>1</Material><Faces>5 6 7</Faces></Mesh>
        <MeshInstance id="1" baseMeshId="2"><Transformations>t2</Transformations></MeshInstance>
        <MeshInstance id="2" baseMeshId="1"></MeshInstance>
    </Objects>)"}});
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(s.objects[4].mesh, s.objects[3].mesh);
  EXPECT_EQ(s.objects[5].mesh, s.objects[0].mesh);
  expect_point(s.objects[5].transform, {0, 0, 0}, {1, 0, 0});
  EXPECT_EQ(s.objects[4].material, 0);
}

}  // namespace
}  // namespace rt
