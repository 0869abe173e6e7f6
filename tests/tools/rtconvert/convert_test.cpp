// rtconvert's parts: the material table (README "Import: the mapping"), the parallelogram
// test for emissive meshes, the extras' exact round trip of floats and doubles, and a whole
// scene through .glb and back with every value equal.
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "convert.h"
#include "course_extras.h"
#include "import_lights.h"
#include "material_map.h"

namespace rtconvert {
namespace {

namespace fs = std::filesystem;

bool has_warning(const Report& r, const std::string& part) {
  for (const auto& w : r.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

void set_colour(aiMaterial& m, const char* key, unsigned type, unsigned index, float r, float g,
                float b) {
  aiColor4D c(r, g, b, 1);
  m.AddProperty(&c, 1, key, type, index);
}

void set_number(aiMaterial& m, const char* key, unsigned type, unsigned index, float v) {
  m.AddProperty(&v, 1, key, type, index);
}

TEST(MaterialMap, MetallicBecomesATintedConductor) {
  aiMaterial m;
  set_colour(m, AI_MATKEY_BASE_COLOR, 0.9f, 0.6f, 0.2f);
  set_number(m, AI_MATKEY_METALLIC_FACTOR, 1);
  set_number(m, AI_MATKEY_ROUGHNESS_FACTOR, 0);
  Report r;
  Material out = map_material(m, "f.glb", r).material;
  EXPECT_EQ(out.type, RT_MATERIAL_CONDUCTOR);
  EXPECT_EQ(out.mirror.x, 0.9f);
  EXPECT_EQ(out.mirror.z, 0.2f);
  EXPECT_EQ(out.refraction_index, 0.2f);
  EXPECT_EQ(out.absorption_index, 3.0f);
  EXPECT_EQ(out.roughness, 0.0f);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];  // A perfect metal maps as documented.
}

TEST(MaterialMap, TransmissionAndIorBecomeADielectric) {
  aiMaterial m;
  set_number(m, AI_MATKEY_TRANSMISSION_FACTOR, 1);
  set_number(m, AI_MATKEY_REFRACTI, 1.33f);
  set_number(m, AI_MATKEY_METALLIC_FACTOR, 0);
  set_number(m, AI_MATKEY_ROUGHNESS_FACTOR, 0.5f);
  Report r;
  Material out = map_material(m, "f.glb", r).material;
  EXPECT_EQ(out.type, RT_MATERIAL_DIELECTRIC);
  EXPECT_EQ(out.refraction_index, 1.33f);
  EXPECT_EQ(out.roughness, 0.25f);  // roughness squared
  EXPECT_FALSE(has_warning(r, "1.5 assumed"));
}

TEST(MaterialMap, PartialOpacityWithoutIorWarnsTwice) {
  aiMaterial m;
  set_number(m, AI_MATKEY_OPACITY, 0.5f);
  Report r;
  Material out = map_material(m, "f.obj", r).material;
  EXPECT_EQ(out.type, RT_MATERIAL_DIELECTRIC);
  EXPECT_EQ(out.refraction_index, 1.5f);
  EXPECT_TRUE(has_warning(r, "partial transparency"));
  EXPECT_TRUE(has_warning(r, "1.5 assumed"));
}

TEST(MaterialMap, ObjBlinnPhongKeepsItsValues) {
  aiMaterial m;
  set_colour(m, AI_MATKEY_COLOR_DIFFUSE, 0.5f, 0.25f, 0.125f);
  set_colour(m, AI_MATKEY_COLOR_SPECULAR, 0.75f, 0.75f, 0.75f);
  set_colour(m, AI_MATKEY_COLOR_AMBIENT, 0.1f, 0.1f, 0.1f);
  set_number(m, AI_MATKEY_SHININESS, 64);
  Report r;
  Material out = map_material(m, "f.obj", r).material;
  EXPECT_EQ(out.type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(out.diffuse.y, 0.25f);
  EXPECT_EQ(out.specular.x, 0.75f);
  EXPECT_EQ(out.ambient.z, 0.1f);
  EXPECT_EQ(out.phong_exponent, 64.0f);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(MaterialMap, ObjIllum3IsAMirrorAndEmissionIsScaled) {
  aiMaterial m;
  set_colour(m, AI_MATKEY_COLOR_SPECULAR, 0.8f, 0.8f, 0.8f);
  set_colour(m, AI_MATKEY_COLOR_EMISSIVE, 1, 0.5f, 0);
  int illum = 3;
  m.AddProperty(&illum, 1, "$mat.illum", 0, 0);
  Report r;
  MappedMaterial out = map_material(m, "f.obj", r);
  EXPECT_EQ(out.material.type, RT_MATERIAL_MIRROR);
  EXPECT_EQ(out.material.mirror.x, 0.8f);
  EXPECT_EQ(out.emission.x, 255.0f);
  EXPECT_EQ(out.emission.y, 127.5f);
}

// Two triangles over the given corners (indices into them).
aiMesh* quad(std::vector<aiVector3D> corners, std::vector<unsigned> indices) {
  aiMesh* m = new aiMesh;
  m->mNumVertices = static_cast<unsigned>(corners.size());
  m->mVertices = new aiVector3D[corners.size()];
  std::copy(corners.begin(), corners.end(), m->mVertices);
  m->mNumFaces = static_cast<unsigned>(indices.size() / 3);
  m->mFaces = new aiFace[m->mNumFaces];
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    m->mFaces[f].mNumIndices = 3;
    m->mFaces[f].mIndices = new unsigned[3]{indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]};
  }
  return m;
}

TEST(ParallelogramLight, ASquareAndASkewedParallelogramMapAnOtherQuadDoesNot) {
  AreaLight a;
  std::unique_ptr<aiMesh> square(
      quad({{0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1}}, {0, 1, 2, 0, 2, 3}));
  ASSERT_TRUE(parallelogram_light(*square, rt::Mat4(), make_float3(5, 5, 5), a));
  EXPECT_EQ(a.area, 1.0f);
  EXPECT_EQ(std::fabs(a.normal.y), 1.0f);
  EXPECT_EQ(a.radiance.x, 5.0f);
  // Translated by the node's transform: the corner moves, the area does not.
  ASSERT_TRUE(
      parallelogram_light(*square, rt::Mat4::translation({0, 3, 0}), make_float3(1, 1, 1), a));
  EXPECT_EQ(a.corner.y, 5.0f);
  std::unique_ptr<aiMesh> skewed(
      quad({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 1, 0}}, {0, 1, 2, 0, 2, 3}));
  ASSERT_TRUE(parallelogram_light(*skewed, rt::Mat4(), make_float3(1, 1, 1), a));
  EXPECT_EQ(a.area, 2.0f);
  std::unique_ptr<aiMesh> trapezoid(
      quad({{0, 0, 0}, {3, 0, 0}, {2, 1, 0}, {1, 1, 0}}, {0, 1, 2, 0, 2, 3}));
  EXPECT_FALSE(parallelogram_light(*trapezoid, rt::Mat4(), make_float3(1, 1, 1), a));
  std::unique_ptr<aiMesh> one(quad({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}));
  EXPECT_FALSE(parallelogram_light(*one, rt::Mat4(), make_float3(1, 1, 1), a));
}

TEST(CourseExtras, FloatsAndDoublesSurviveTheJsonText) {
  Material m{};
  m.type = RT_MATERIAL_DIELECTRIC;
  m.diffuse = make_float3(0.1f, 1e-30f, 3.4e38f);
  m.absorption = make_float3(0.3f, 0.7f, 1.0f / 3.0f);
  m.refraction_index = 1.5f;
  m.phong_exponent = 123.456f;
  Material back = material_from_json(json::parse(material_to_json(m).dump()));
  EXPECT_EQ(std::memcmp(&m, &back, sizeof m), 0);

  rt::CameraDesc c;
  c.position = {0.1, 1.0 / 3.0, -1e-300};
  c.gaze = {0, 0, -1};
  c.up = {0, 1, 0};
  c.left = -0.7;
  c.right = 0.6;
  c.width = 7;
  c.height = 5;
  c.image_name = "x.png";
  rt::CameraDesc cb = camera_from_json(json::parse(camera_to_json(c).dump()));
  EXPECT_EQ(cb.position.y, c.position.y);
  EXPECT_EQ(cb.position.z, c.position.z);
  EXPECT_EQ(cb.left, c.left);
  EXPECT_EQ(cb.height, 5);
  EXPECT_EQ(cb.image_name, "x.png");
}

class GlbRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rt_convert_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Every value the renderer reads comes back equal: two instances of one mesh with their own
// materials and transforms, a sphere through a rotation, motion blur, an off-centre camera
// with depth of field, both kinds of light, and the scene's settings.
TEST_F(GlbRoundTrip, EveryValueComesBackEqual) {
  const fs::path xml = dir_ / "in.xml";
  std::ofstream(xml) << R"(<Scene>
  <BackgroundColor>1 2 3</BackgroundColor><ShadowRayEpsilon>0.00123</ShadowRayEpsilon>
  <MaxRecursionDepth>4</MaxRecursionDepth>
  <Cameras><Camera id="1"><Position>0.1 0.2 5</Position><Gaze>0 0.1 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 0.8 -0.5 0.7</NearPlane><NearDistance>1.5</NearDistance>
    <ImageResolution>30 20</ImageResolution><NumSamples>4</NumSamples>
    <ApertureSize>0.1</ApertureSize><FocusDistance>4</FocusDistance><ImageName>a.png</ImageName>
  </Camera></Cameras>
  <Lights><AmbientLight>10 20 30</AmbientLight>
    <PointLight id="1"><Position>1 2 3</Position><Intensity>100 50 25</Intensity></PointLight>
    <AreaLight id="1"><Position>0 4 0</Position><Normal>0 -1 0.1</Normal><Size>0.7</Size>
      <Radiance>300 300 300</Radiance></AreaLight></Lights>
  <Materials>
    <Material id="1"><DiffuseReflectance>0.1 0.2 0.3</DiffuseReflectance>
      <SpecularReflectance>0.4 0.5 0.6</SpecularReflectance><PhongExponent>37</PhongExponent></Material>
    <Material id="2" type="dielectric"><RefractionIndex>1.45</RefractionIndex>
      <AbsorptionCoefficient>0.01 0.02 0.03</AbsorptionCoefficient><Roughness>0.1</Roughness></Material>
    <Material id="3" type="conductor"><MirrorReflectance>0.9 0.8 0.7</MirrorReflectance>
      <RefractionIndex>0.2</RefractionIndex><AbsorptionIndex>3.1</AbsorptionIndex></Material>
  </Materials>
  <Transformations><Rotation id="1">33 1 2 3</Rotation><Translation id="1">0.1 0.2 0.3</Translation>
    <Scaling id="1">1 2 0.5</Scaling></Transformations>
  <VertexData>0 0 0  1 0 0  0 1 0  0 0 1  0.3 0.3 0.3</VertexData>
  <Objects>
    <Mesh id="1" shadingMode="smooth"><Material>1</Material><Faces>1 2 3 1 3 4 1 4 2 2 4 3</Faces>
      <Transformations>r1 t1</Transformations></Mesh>
    <MeshInstance id="2" baseMeshId="1"><Material>3</Material><Transformations>s1</Transformations>
      <MotionBlur>0 1 0</MotionBlur></MeshInstance>
    <Sphere id="3"><Material>2</Material><Center>5</Center><Radius>0.25</Radius>
      <Transformations>r1</Transformations></Sphere>
  </Objects></Scene>)";
  rt::SceneDesc a = rt::load_scene(xml.string());
  Report r;
  const std::string glb = (dir_ / "s.glb").string();
  export_with_assimp(a, glb, "glb2", r);
  ImportedScene in = import_with_assimp(glb, 640, true, r);
  write_course_xml(in, (dir_ / "back.xml").string(), r);
  rt::SceneDesc b = rt::load_scene((dir_ / "back.xml").string());

  ASSERT_EQ(b.cameras.size(), 1u);
  const rt::CameraDesc &ca = a.cameras[0], &cb = b.cameras[0];
  EXPECT_EQ(std::memcmp(&ca.position, &cb.position, sizeof ca.position), 0);
  EXPECT_EQ(std::memcmp(&ca.gaze, &cb.gaze, sizeof ca.gaze), 0);
  EXPECT_EQ(ca.left, cb.left);
  EXPECT_EQ(ca.top, cb.top);
  EXPECT_EQ(ca.near_distance, cb.near_distance);
  EXPECT_EQ(ca.aperture, cb.aperture);
  EXPECT_EQ(ca.samples, cb.samples);
  EXPECT_EQ(cb.image_name, "a.png");
  EXPECT_EQ(std::memcmp(&a.background, &b.background, sizeof a.background), 0);
  EXPECT_EQ(std::memcmp(&a.ambient, &b.ambient, sizeof a.ambient), 0);
  EXPECT_EQ(a.shadow_epsilon, b.shadow_epsilon);
  EXPECT_EQ(a.max_depth, b.max_depth);
  ASSERT_EQ(b.materials.size(), a.materials.size());
  for (size_t i = 0; i < a.materials.size(); ++i)
    EXPECT_EQ(std::memcmp(&a.materials[i], &b.materials[i], sizeof(Material)), 0) << i;
  ASSERT_EQ(b.point_lights.size(), 1u);
  EXPECT_EQ(std::memcmp(&a.point_lights[0], &b.point_lights[0], sizeof(PointLight)), 0);
  ASSERT_EQ(b.area_lights.size(), 1u);
  const AreaLight &la = a.area_lights[0], &lb = b.area_lights[0];
  EXPECT_EQ(std::memcmp(&la.corner, &lb.corner, sizeof la.corner), 0);
  EXPECT_EQ(std::memcmp(&la.edge1, &lb.edge1, sizeof la.edge1), 0);
  EXPECT_EQ(std::memcmp(&la.radiance, &lb.radiance, sizeof la.radiance), 0);
  ASSERT_EQ(b.objects.size(), 3u);
  ASSERT_EQ(b.meshes.size(), 1u);  // The instance shares the mesh: no copied geometry.
  EXPECT_TRUE(b.meshes[0].smooth);
  EXPECT_EQ(b.meshes[0].triangles, a.meshes[0].triangles);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.objects[i].kind, b.objects[i].kind) << i;
    EXPECT_EQ(a.objects[i].material, b.objects[i].material) << i;
    EXPECT_EQ(a.objects[i].transform.m, b.objects[i].transform.m) << i;
    EXPECT_EQ(std::memcmp(&a.objects[i].motion, &b.objects[i].motion, sizeof(rt::Vec3d)), 0) << i;
  }
}

TEST_F(GlbRoundTrip, UnreadableFilesNameTheFile) {
  Report r;
  const std::string junk = (dir_ / "junk.fbx").string();
  std::ofstream(junk) << "not a model";
  try {
    import_with_assimp(junk, 640, true, r);
    FAIL() << "no error";
  } catch (const ConvertError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(junk + ": ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace rtconvert
