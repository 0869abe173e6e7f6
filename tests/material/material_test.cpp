// Tests for the material dispatch (cl/material/material.h): what the ray tree's Scatter
// (cl/integrator/ray_tree.h) pushes for each
// material type (direction, weight, medium, key, depth, side of the surface), against
// reflection, Snell's law and the Fresnel terms in closed form.
//
// Tolerances: directions and weights built from dyadic operands are exact; refracted
// directions and Fresnel weights allow a few float roundings (1e-6).
#include <gtest/gtest.h>

#include <cmath>

#include "cl/integrator/ray_tree.h"

namespace rt {
namespace {

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

struct MaterialScene {
  SceneHeader header{};
  SceneData sd{};
  Material material{};
  InstanceTextures untextured{{-1, -1, -1, -1}};  // The hit's instance 0 lists no texture.
  MaterialScene(int type) {
    header.features = RT_FEATURE_ALL;
    sd.header = &header;
    sd.materials = &material;
    sd.instance_textures = &untextured;
    material.type = type;
    material.mirror = V(0.5f, 0.25f, 1.0f);
    material.refraction_index = 1.5f;
    material.absorption = V(0.1f, 0.2f, 0.3f);
  }
};

// A point of the plane z = 0 hit from direction wo, seen from the side wo is on.
SurfacePoint PlanePoint(float3 wo) {
  SurfacePoint s{};
  s.p = V(0, 0, 0);
  s.n = s.ng = V(0, 0, 1);
  s.wo = wo;
  s.scale = 1;
  s.time = 0.25f;
  s.front = Dot(wo, s.ng) > 0.0f;
  FaceForward(&s);
  return s;
}

RayTask Parent(uint key) {
  return MakeTask(MakeRay(V(0, 0, 1), V(0, 0, -1), RT_INFINITY, 0.25f), V(1, 2, 4), V(0, 0, 0), key,
                  3, 0);
}

RayStack ScatterOnce(MaterialScene& scene, float3 wo, RayTask task) {
  SurfacePoint s = PlanePoint(wo);
  Material m = EvaluateMaterial(&scene.sd, &s);
  RayStack stack;
  stack.size = 0;
  RaySampler rs = MakeRaySampler(MakeSampleKey(1, 2, 4, 2, 0), task.key, 0);
  Scatter(&scene.sd, &m, &s, &task, rs, &stack);
  return stack;
}

TEST(MaterialEvaluate, GathersTheHitsMaterial) {
  MaterialScene scene(RT_MATERIAL_PLAIN);
  scene.material.diffuse = V(0.25f, 0.5f, 0.75f);
  SurfacePoint s = PlanePoint(V(0, 0, 1));
  Material m = EvaluateMaterial(&scene.sd, &s);
  EXPECT_EQ(m.diffuse.y, 0.5f);
  EXPECT_EQ(m.type, RT_MATERIAL_PLAIN);
}

TEST(MaterialScatter, PlainSurfacesSendNoRay) {
  MaterialScene scene(RT_MATERIAL_PLAIN);
  EXPECT_EQ(ScatterOnce(scene, V(0, 0.6f, 0.8f), Parent(9)).size, 0);
}

TEST(MaterialScatter, MirrorReflectsWithItsReflectance) {
  MaterialScene scene(RT_MATERIAL_MIRROR);
  RayStack st = ScatterOnce(scene, V(0, 0.6f, 0.8f), Parent(9));
  ASSERT_EQ(st.size, 1);
  const RayTask& r = st.tasks[0];
  EXPECT_EQ(r.ray.direction.y, -0.6f);
  EXPECT_EQ(r.ray.direction.z, 0.8f);
  EXPECT_GT(r.ray.origin.z, 0.0f);  // Spawned above the surface.
  EXPECT_EQ(r.ray.time, 0.25f);
  EXPECT_EQ(r.weight.x, 0.5f);
  EXPECT_EQ(r.weight.y, 0.5f);
  EXPECT_EQ(r.weight.z, 4.0f);
  EXPECT_EQ(r.key, HashCombine(9u, RT_CHILD_REFLECTED));
  EXPECT_EQ(r.depth, 4);
  EXPECT_EQ(r.inside, 0);
}

TEST(MaterialScatter, ConductorScalesByItsFresnelTerm) {
  MaterialScene scene(RT_MATERIAL_CONDUCTOR);
  scene.material.refraction_index = 0.2f;
  scene.material.absorption_index = 3.0f;
  RayStack st = ScatterOnce(scene, V(0, 0, 1), Parent(9));
  ASSERT_EQ(st.size, 1);
  // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
  double fr = (0.64 + 9.0) / (1.44 + 9.0);
  EXPECT_NEAR(st.tasks[0].weight.x, 0.5 * fr, 1e-6);
  EXPECT_NEAR(st.tasks[0].weight.z, 4.0 * fr, 1e-6);
  EXPECT_EQ(st.tasks[0].ray.direction.z, 1.0f);
}

TEST(MaterialScatter, DielectricSplitsByFresnelAndObeysSnell) {
  MaterialScene scene(RT_MATERIAL_DIELECTRIC);
  const float3 wo = V(0, 0.6f, 0.8f);  // sin_i = 0.6 from air into index 1.5.
  RayStack st = ScatterOnce(scene, wo, Parent(9));
  ASSERT_EQ(st.size, 2);
  const RayTask& refl = st.tasks[0];
  const RayTask& refr = st.tasks[1];  // Pushed last: followed first.
  float cos_t;
  float fr = FrDielectric(0.8f, 1.0f, 1.5f, &cos_t);
  EXPECT_NEAR(refl.weight.x + refr.weight.x, 1.0, 1e-6);  // Energy is split, not lost.
  EXPECT_NEAR(refl.weight.x, fr, 1e-7);
  EXPECT_NEAR(refr.ray.direction.y, -0.6 / 1.5, 1e-6);  // sin_t = sin_i / eta.
  EXPECT_LT(refr.ray.direction.z, 0.0f);
  EXPECT_LT(refr.ray.origin.z, 0.0f);  // Spawned below the surface.
  EXPECT_EQ(refr.inside, 1);
  EXPECT_EQ(refr.medium.y, 0.2f);  // Entering: the glass's absorption.
  EXPECT_EQ(refr.key, HashCombine(9u, RT_CHILD_REFRACTED));
  EXPECT_EQ(refl.inside, 0);
  EXPECT_EQ(refl.medium.y, 0.0f);
}

TEST(MaterialScatter, DielectricReflectsTotallyBeyondTheCriticalAngle) {
  MaterialScene scene(RT_MATERIAL_DIELECTRIC);
  RayTask inside = Parent(9);
  inside.inside = 1;
  inside.medium = scene.material.absorption;
  // From inside, sin_i = 0.8 > 1 / 1.5.
  RayStack st = ScatterOnce(scene, V(0, 0.8f, -0.6f), inside);
  ASSERT_EQ(st.size, 1);
  EXPECT_EQ(st.tasks[0].weight.x, 1.0f);
  EXPECT_EQ(st.tasks[0].inside, 1);  // Still inside the glass, in its medium.
  EXPECT_EQ(st.tasks[0].medium.z, 0.3f);
  EXPECT_LT(st.tasks[0].ray.origin.z, 0.0f);
}

TEST(MaterialScatter, DielectricChoiceFollowsOneRayAtFullWeight) {
  MaterialScene scene(RT_MATERIAL_DIELECTRIC);
  scene.header.flags = RT_FLAG_FRESNEL_CHOICE;
  int reflected = 0;
  for (uint key = 0; key < 2000; ++key) {
    RayStack st = ScatterOnce(scene, V(0, 0.6f, 0.8f), Parent(key));
    ASSERT_EQ(st.size, 1);
    EXPECT_EQ(st.tasks[0].weight.y, 2.0f);
    reflected += st.tasks[0].ray.direction.z > 0.0f;
  }
  // Reflected with probability fr ~ 0.042: 84 expected of 2000, sd ~ 9; 5 sd either way.
  float cos_t;
  double expect = 2000.0 * FrDielectric(0.8f, 1.0f, 1.5f, &cos_t);
  EXPECT_NEAR(reflected, expect, 5 * std::sqrt(expect));
}

TEST(RayTree, PushingBeyondTheStackFailsAnAssertionInDebugBuilds) {
#ifdef NDEBUG
  GTEST_SKIP() << "RT_ASSERT is empty in release builds (NDEBUG); configure a Debug build";
#else
  RayStack stack;
  stack.size = RT_TASK_STACK;
  EXPECT_DEATH(PushRay(&stack, Parent(1)), "");
#endif
}

}  // namespace
}  // namespace rt
