// Export through Assimp: the scene becomes an aiScene (one node per object, one mesh per
// (geometry, material) pair, since glTF and OBJ bind materials to meshes, not nodes) and
// Assimp writes it. Assimp 5.2's glTF exporter writes neither cameras, nor lights, nor
// extras, so for .glb they are added to its JSON afterwards (gltf_extras_export.cpp).
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "convert.h"
#include "gltf_export.h"
#include "prepare/flat_scene.h"

namespace rtconvert {
namespace {

// A unit sphere (smooth normals are its positions); spheres are kept exactly in extras.
// Its seam lies at phi = atan2(z, x) = pi, where the course's spherical texture
// coordinates u = (pi - phi) / (2 pi), v = theta / pi wrap, so they run on without a jump.
rt::MeshDesc unit_sphere() {
  const int rings = 16, segments = 32;
  rt::MeshDesc m;
  m.smooth = true;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      double th = M_PI * r / rings, ph = M_PI + 2 * M_PI * s / segments;
      m.positions.push_back(
          {std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
      m.uvs.push_back({1.0 - static_cast<double>(s) / segments, static_cast<double>(r) / rings});
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      int a = r * (segments + 1) + s, b = a + segments + 1;
      if (r > 0) m.triangles.push_back({a, a + 1, b});
      if (r < rings - 1) m.triangles.push_back({a + 1, b + 1, b});
    }
  return m;
}

aiMesh* make_mesh(const rt::MeshDesc& desc, unsigned material, const std::string& name) {
  aiMesh* m = new aiMesh;
  m->mName = name;
  m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  m->mMaterialIndex = material;
  m->mNumVertices = static_cast<unsigned>(desc.positions.size());
  m->mVertices = new aiVector3D[m->mNumVertices];
  for (unsigned i = 0; i < m->mNumVertices; ++i) {
    const rt::Vec3d& p = desc.positions[i];
    m->mVertices[i] =
        aiVector3D(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
  }
  // Flat meshes carry no normals: glTF viewers then shade them flat, as the course does.
  if (desc.smooth) {
    std::vector<rt::Vec3d> n = rt::vertex_normals(desc);
    m->mNormals = new aiVector3D[m->mNumVertices];
    for (unsigned i = 0; i < m->mNumVertices; ++i)
      m->mNormals[i] = aiVector3D(static_cast<float>(n[i].x), static_cast<float>(n[i].y),
                                  static_cast<float>(n[i].z));
  }
  // Assimp's texture origin is the bottom left (as OBJ's), the course's the top left.
  if (!desc.uvs.empty()) {
    m->mNumUVComponents[0] = 2;
    m->mTextureCoords[0] = new aiVector3D[m->mNumVertices];
    for (unsigned i = 0; i < m->mNumVertices; ++i)
      m->mTextureCoords[0][i] = aiVector3D(static_cast<float>(desc.uvs[i][0]),
                                           static_cast<float>(1.0 - desc.uvs[i][1]), 0);
  }
  m->mNumFaces = static_cast<unsigned>(desc.triangles.size());
  m->mFaces = new aiFace[m->mNumFaces];
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    m->mFaces[f].mNumIndices = 3;
    m->mFaces[f].mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k)
      m->mFaces[f].mIndices[k] = static_cast<unsigned>(desc.triangles[f][k]);
  }
  return m;
}

// The Blinn-Phong values as OBJ/MTL has them (Kd, Ks, Ka, Ns, Ni); glTF's native values
// are written into the JSON later. For OBJ a replace_kd / replace_ks image map becomes
// map_Kd / map_Ks, named relative to the MTL file, with Kd / Ks = 255 / Normalizer (the
// factor other tools multiply the texture by).
aiMaterial* make_material(const rt::SceneDesc& s, const MaterialVariant& v, const std::string& name,
                          const std::vector<std::string>& obj_images) {
  const Material& mat = s.materials[v.material];
  aiMaterial* m = new aiMaterial;
  aiString ai_name(name);
  m->AddProperty(&ai_name, AI_MATKEY_NAME);
  auto colour = [](float3 c) { return aiColor3D(c.x, c.y, c.z); };
  aiColor3D kd = colour(mat.diffuse), ks = colour(mat.specular), ka = colour(mat.ambient);
  if (!obj_images.empty())
    for (auto [decal, type] : {std::pair{RT_DECAL_REPLACE_KD, aiTextureType_DIFFUSE},
                               std::pair{RT_DECAL_REPLACE_KS, aiTextureType_SPECULAR}}) {
      int t = image_map(s, v.textures, decal);
      if (t < 0) continue;
      aiString file(obj_images[s.textures[t].image]);
      m->AddProperty(&file, AI_MATKEY_TEXTURE(type, 0));
      float k = 255.0f / s.textures[t].desc.normalizer;
      (decal == RT_DECAL_REPLACE_KD ? kd : ks) = aiColor3D(k, k, k);
    }
  m->AddProperty(&kd, 1, AI_MATKEY_COLOR_DIFFUSE);
  m->AddProperty(&ks, 1, AI_MATKEY_COLOR_SPECULAR);
  m->AddProperty(&ka, 1, AI_MATKEY_COLOR_AMBIENT);
  m->AddProperty(&mat.phong_exponent, 1, AI_MATKEY_SHININESS);
  m->AddProperty(&mat.refraction_index, 1, AI_MATKEY_REFRACTI);
  return m;
}

// Emission as OBJ's Ke and glTF's emissive colour hold it: radiance / 255, so that 1 is
// white (the glTF JSON then splits it into a factor and KHR_materials_emissive_strength).
aiMaterial* make_emitter(const AreaLight& a, size_t index) {
  aiMaterial* m = new aiMaterial;
  aiString name(area_light_name(index));
  m->AddProperty(&name, AI_MATKEY_NAME);
  aiColor3D black(0, 0, 0), ke(a.radiance.x / kRadianceScale, a.radiance.y / kRadianceScale,
                               a.radiance.z / kRadianceScale);
  m->AddProperty(&black, 1, AI_MATKEY_COLOR_DIFFUSE);
  m->AddProperty(&ke, 1, AI_MATKEY_COLOR_EMISSIVE);
  return m;
}

// The parallelogram as two triangles (corner, corner + e1, corner + e1 + e2, corner + e2).
rt::MeshDesc light_quad(const AreaLight& a) {
  rt::MeshDesc m;
  rt::Vec3d c{a.corner.x, a.corner.y, a.corner.z}, e1{a.edge1.x, a.edge1.y, a.edge1.z},
      e2{a.edge2.x, a.edge2.y, a.edge2.z};
  m.positions = {c, c + e1, c + e1 + e2, c + e2};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

aiMatrix4x4 to_ai(const rt::Mat4& t) {
  aiMatrix4x4 a;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a[r][c] = static_cast<float>(t(r, c));
  return a;
}

// The image files as the MTL file names them: relative to its folder where possible.
std::vector<std::string> mtl_image_names(const std::vector<ImageFile>& images,
                                         const std::string& path) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  const fs::path dir = fs::absolute(fs::path(path)).parent_path();
  for (const ImageFile& f : images) {
    std::error_code ec;
    fs::path rel = fs::relative(fs::absolute(f.path), dir, ec);
    out.push_back(ec || rel.empty() ? fs::absolute(f.path).string() : rel.generic_string());
  }
  return out;
}

}  // namespace

std::vector<MaterialVariant> material_variants(const rt::SceneDesc& s) {
  std::vector<MaterialVariant> v;
  for (size_t i = 0; i < s.materials.size(); ++i) v.push_back({static_cast<int>(i), {}});
  for (const auto& o : s.objects)
    if (!o.textures.empty() && variant_of(v, o) < 0) v.push_back({o.material, o.textures});
  return v;
}

int variant_of(const std::vector<MaterialVariant>& variants, const rt::ObjectDesc& o) {
  for (size_t i = 0; i < variants.size(); ++i)
    if (variants[i].material == o.material && variants[i].textures == o.textures)
      return static_cast<int>(i);
  return -1;
}

std::string variant_name(const std::vector<MaterialVariant>& variants, size_t i) {
  return variants[i].textures.empty()
             ? material_name(variants[i].material)
             : material_name(variants[i].material) + "_textured" + std::to_string(i);
}

int image_map(const rt::SceneDesc& s, const std::vector<int>& textures, int decal) {
  for (int t : textures)
    if (s.textures[t].desc.type == RT_TEXTURE_IMAGE && s.textures[t].desc.decal == decal) return t;
  return -1;
}

void export_with_assimp(const rt::SceneDesc& s, const std::string& path, const std::string& format,
                        Report& report, const std::vector<ImageFile>& images) {
  for (const auto& t : s.textures)
    if (t.image >= static_cast<int>(images.size()))
      throw ConvertError(path + ": " + t.element + ": its image file is not known");
  aiScene* scene = new aiScene;
  scene->mRootNode = new aiNode("root");
  // The course's materials (with the textures of their objects), then one emissive
  // material per area light. glTF's textures are added to its JSON afterwards.
  const std::vector<MaterialVariant> variants = material_variants(s);
  const std::vector<std::string> obj_images =
      format == "obj" ? mtl_image_names(images, path) : std::vector<std::string>();
  scene->mNumMaterials = static_cast<unsigned>(variants.size() + s.area_lights.size());
  scene->mMaterials = new aiMaterial*[scene->mNumMaterials];
  for (size_t i = 0; i < variants.size(); ++i)
    scene->mMaterials[i] = make_material(s, variants[i], variant_name(variants, i), obj_images);
  for (size_t i = 0; i < s.area_lights.size(); ++i)
    scene->mMaterials[variants.size() + i] = make_emitter(s.area_lights[i], i);

  const rt::MeshDesc sphere = unit_sphere();
  std::map<std::pair<int, int>, unsigned> pair_mesh;  // (mesh or -1 for sphere, variant)
  std::vector<aiMesh*> meshes;
  std::vector<aiNode*> nodes;
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const rt::ObjectDesc& o = s.objects[i];
    const int geometry = o.kind == rt::ObjectDesc::kSphere ? -1 : o.mesh;
    const int variant = variant_of(variants, o);
    auto [it, added] =
        pair_mesh.emplace(std::make_pair(geometry, variant), static_cast<unsigned>(meshes.size()));
    if (added)
      meshes.push_back(
          make_mesh(geometry < 0 ? sphere : s.meshes[geometry], static_cast<unsigned>(variant),
                    (geometry < 0 ? std::string("sphere") : "mesh" + std::to_string(geometry)) +
                        "_" + variant_name(variants, variant)));
    aiNode* n = new aiNode(object_name(i));
    n->mParent = scene->mRootNode;
    n->mTransformation = to_ai(o.transform);
    n->mNumMeshes = 1;
    n->mMeshes = new unsigned[1]{it->second};
    nodes.push_back(n);
  }
  // Area lights as emissive quads, so that other tools see them (and read them back as
  // lights: rtconvert's importer turns emissive parallelograms into area lights).
  for (size_t i = 0; i < s.area_lights.size(); ++i) {
    aiNode* n = new aiNode(area_light_name(i));
    n->mParent = scene->mRootNode;
    n->mNumMeshes = 1;
    n->mMeshes = new unsigned[1]{static_cast<unsigned>(meshes.size())};
    meshes.push_back(make_mesh(light_quad(s.area_lights[i]),
                               static_cast<unsigned>(variants.size() + i), area_light_name(i)));
    nodes.push_back(n);
  }
  scene->mNumMeshes = static_cast<unsigned>(meshes.size());
  scene->mMeshes = new aiMesh*[meshes.size()];
  std::copy(meshes.begin(), meshes.end(), scene->mMeshes);
  scene->mRootNode->mNumChildren = static_cast<unsigned>(nodes.size());
  scene->mRootNode->mChildren = new aiNode*[nodes.size()];
  std::copy(nodes.begin(), nodes.end(), scene->mRootNode->mChildren);

  Assimp::Exporter exporter;
  if (exporter.Export(scene, format, path) != AI_SUCCESS) {
    std::string err = exporter.GetErrorString();
    delete scene;
    std::remove(path.c_str());
    throw ConvertError(path + ": Assimp export (" + format + ") failed: " + err);
  }
  delete scene;

  if (format == "glb2") {
    try {
      add_course_data_to_glb(s, path, images, report);
    } catch (...) {
      std::remove(path.c_str());  // Not a .glb without its cameras and lights.
      throw;
    }
    return;
  }
  // OBJ and MTL: what they cannot hold, said once.
  int spheres = 0, moving = 0, special = 0;
  for (const auto& o : s.objects) {
    spheres += o.kind == rt::ObjectDesc::kSphere;
    moving += o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0;
  }
  for (const auto& m : s.materials) special += m.type != RT_MATERIAL_PLAIN;
  report.warn(path + ": OBJ has no cameras or lights: " + std::to_string(s.cameras.size()) +
              " cameras and " + std::to_string(s.point_lights.size()) +
              " point lights not written; " + std::to_string(s.area_lights.size()) +
              " area lights written as emissive quads (Ke = radiance / 255)");
  report.warn(path + ": OBJ has no instances or transforms: " + std::to_string(s.objects.size()) +
              " objects written as world-space copies");
  if (spheres)
    report.warn(path + ": " + std::to_string(spheres) + " spheres tessellated (512 triangles)");
  if (moving) report.warn(path + ": " + std::to_string(moving) + " motion-blur vectors lost");
  if (special)
    report.warn(path + ": MTL: " + std::to_string(special) +
                " mirror/conductor/dielectric materials written as their Blinn-Phong part "
                "(MirrorReflectance, AbsorptionIndex, AbsorptionCoefficient, Roughness lost)");
}

}  // namespace rtconvert
