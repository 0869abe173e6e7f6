// Import through Assimp: nodes become objects (a mesh used by several nodes, or identical
// geometry under several names, becomes one Mesh and MeshInstances), materials follow
// material_map.cpp, emissive parallelograms become area lights. A glTF file written by
// rtconvert carries extras.ceng795 on its scene, materials, nodes, cameras and lights; those
// exact values replace the approximate native ones.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "convert.h"
#include "course_extras.h"
#include "gltf_export.h"
#include "import_lights.h"
#include "import_mesh.h"
#include "material_map.h"
#include "texture_import.h"

namespace rtconvert {
namespace {

using rt::Mat4;
using rt::Vec3d;

std::string file_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return s.substr(0, 40);
}

class Importer {
 public:
  Importer(const std::string& path, Report& report) : file_(path), report_(report) {}
  ImportedScene run(int default_width, bool use_extras);

 private:
  void walk(const aiNode* node, const Mat4& parent);
  int course_mesh(unsigned ai_index, bool smooth, bool uvs);
  void name_images();
  int course_material(unsigned ai_index);
  void add_object(const aiNode* node, unsigned ai_mesh, const Mat4& world);

  std::string file_;
  Report& report_;
  const aiScene* ai_ = nullptr;
  json gltf_;            // The file's glTF JSON, when it is glTF.
  bool course_ = false;  // Written by rtconvert: extras.ceng795 present.
  ImportedScene out_;
  std::map<unsigned, int> mesh_of_ai_, material_of_ai_;
  // Mapped when first used: files often carry unused (default) materials.
  const MappedMaterial& mapped(unsigned ai_index);
  std::map<unsigned, MappedMaterial> mapped_;
  std::map<std::string, const json*> node_extras_;
  std::unique_ptr<TextureImporter> textures_;
  int smooth_guessed_ = 0;
};

const MappedMaterial& Importer::mapped(unsigned ai_index) {
  auto it = mapped_.find(ai_index);
  if (it != mapped_.end()) return it->second;
  const aiMaterial& m = *ai_->mMaterials[ai_index];
  MappedMaterial out = map_material(m, file_, report_);
  // Assimp 5.2 does not read KHR_materials_emissive_strength (emission above 1): from the
  // JSON, by the material's name.
  float unused;
  if (gltf_.is_object() && gltf_.contains("materials") && gltf_["materials"].is_array() &&
      m.Get(AI_MATKEY_EMISSIVE_INTENSITY, unused) != AI_SUCCESS)
    for (const json& g : gltf_["materials"])
      if (g.is_object() && g.value("name", "") == out.name && g.contains("extensions") &&
          g["extensions"].contains("KHR_materials_emissive_strength")) {
        float k =
            g["extensions"]["KHR_materials_emissive_strength"].value("emissiveStrength", 1.0f);
        out.emission = make_float3(out.emission.x * k, out.emission.y * k, out.emission.z * k);
        break;
      }
  return mapped_.emplace(ai_index, out).first->second;
}

int Importer::course_material(unsigned ai_index) {
  auto it = material_of_ai_.find(ai_index);
  if (it != material_of_ai_.end()) return it->second;
  out_.scene.materials.push_back(mapped(ai_index).material);
  return material_of_ai_[ai_index] = static_cast<int>(out_.scene.materials.size()) - 1;
}

int Importer::course_mesh(unsigned ai_index, bool smooth, bool uvs) {
  auto it = mesh_of_ai_.find(ai_index);
  if (it != mesh_of_ai_.end()) return it->second;
  const aiMesh& m = *ai_->mMeshes[ai_index];
  rt::MeshDesc d = mesh_of(m, uvs && m.HasTextureCoords(0), !course_ && !uvs);
  if (!course_ && !d.uvs.empty())
    if (int n = wrap_texture_coordinates(d))
      report_.warn(file_ + ": " + d.element + ": " + std::to_string(n) +
                   " triangles span more than one repeat of their texture; the course "
                   "clamps to the edge texels there");
  for (const Vec3d& p : d.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw ConvertError(file_ + ": " + d.element + ": a vertex position is not finite");
  d.smooth = smooth;
  // The same geometry under another name (glTF meshes split per material) is shared too.
  for (size_t k = 0; k < out_.scene.meshes.size(); ++k)
    if (out_.scene.meshes[k].smooth == smooth && same_geometry(out_.scene.meshes[k], d))
      return mesh_of_ai_[ai_index] = static_cast<int>(k);
  out_.scene.meshes.push_back(std::move(d));
  out_.mesh_names.push_back(file_safe(ai_->mMeshes[ai_index]->mName.C_Str()));
  return mesh_of_ai_[ai_index] = static_cast<int>(out_.scene.meshes.size()) - 1;
}

void Importer::add_object(const aiNode* node, unsigned ai_mesh, const Mat4& world) {
  const aiMesh& m = *ai_->mMeshes[ai_mesh];
  const std::string name = node->mName.C_Str();
  if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
    report_.warn(file_ + ": mesh '" + m.mName.C_Str() + "': points and lines are not rendered");
    return;
  }
  rt::ObjectDesc o;
  o.element = "node '" + name + "'";
  auto extras = node_extras_.find(name);
  if (course_ && extras != node_extras_.end()) {
    const json& e = *extras->second;
    if (e.at("kind") == "areaLight") return;  // The scene's extras hold the exact light.
    o.transform = mat4_from(e.at("matrix"));
    o.motion = vec3d_from(e.at("motionBlur"));
    o.material = e.at("material").get<int>();
    if (o.material < 0 || o.material >= static_cast<int>(out_.scene.materials.size()))
      throw ConvertError(file_ + ": node '" + name + "': extras." + kExtrasKey + ".material " +
                         std::to_string(o.material) + " names no material");
    // Texture maps and object lights: absent from files of rtconvert before they were kept.
    o.textures = e.value("textures", std::vector<int>());
    for (int t : o.textures)
      if (t < 0 || t >= static_cast<int>(out_.scene.textures.size()))
        throw ConvertError(file_ + ": node '" + name + "': extras." + kExtrasKey +
                           ".textures names no texture " + std::to_string(t));
    o.emits = e.value("emits", false);
    if (o.emits) o.radiance = vec3d_from(e.at("radiance"));
    if (e.at("kind") == "sphere") {
      o.kind = rt::ObjectDesc::kSphere;
    } else {
      o.mesh = course_mesh(ai_mesh, e.at("smooth").get<bool>(), true);
    }
    out_.scene.objects.push_back(o);
    return;
  }
  const MappedMaterial& mat = mapped(m.mMaterialIndex);
  if (mat.emission.x > 0 || mat.emission.y > 0 || mat.emission.z > 0) {
    AreaLight a;
    if (parallelogram_light(m, world, mat.emission, a)) {
      out_.scene.area_lights.push_back(a);
      return;
    }
    report_.warn(file_ + ": node '" + name +
                 "': emissive mesh is not a parallelogram: kept as geometry, emission dropped");
  }
  bool ok;
  world.affine_inverse(&ok);
  if (!ok) {
    report_.warn(file_ + ": node '" + name + "': singular transform, node skipped");
    return;
  }
  bool smooth = has_smooth_normals(m);
  if (smooth && !mesh_of_ai_.count(ai_mesh)) ++smooth_guessed_;
  o.textures = textures_->maps_of(m.mMaterialIndex, mat);
  if (!o.textures.empty() && !m.HasTextureCoords(0)) {
    report_.warn(file_ + ": mesh '" + m.mName.C_Str() +
                 "': textured material but no texture coordinates: textures dropped");
    o.textures.clear();
  }
  o.mesh = course_mesh(ai_mesh, smooth, !o.textures.empty());
  o.material = course_material(m.mMaterialIndex);
  o.transform = world;
  out_.scene.objects.push_back(o);
}

void Importer::walk(const aiNode* node, const Mat4& parent) {
  Mat4 local = from_ai(node->mTransformation);
  // Some writers leave float noise in the last row (0 0 0 0.9999999); the course's
  // transforms are affine, so that is cleaned, and a truly projective matrix is refused.
  for (int c = 0; c < 4; ++c) {
    if (std::fabs(local(3, c) - (c == 3)) > 1e-4)
      throw ConvertError(file_ + ": node '" + node->mName.C_Str() +
                         "': projective transform (last row not 0 0 0 1)");
    local(3, c) = c == 3;
  }
  Mat4 world = parent * local;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) add_object(node, node->mMeshes[i], world);
  for (unsigned i = 0; i < node->mNumChildren; ++i) walk(node->mChildren[i], world);
}

// Renders are named after the input (model.png; model_<camera>.png for several cameras),
// so that two imported models rendered in one folder do not overwrite each other.
void Importer::name_images() {
  auto& cams = out_.scene.cameras;
  const std::string stem = std::filesystem::path(file_).stem().string();
  for (size_t i = 0; i < cams.size(); ++i) {
    std::string camera = i < ai_->mNumCameras ? file_safe(ai_->mCameras[i]->mName.C_Str()) : "";
    if (camera.empty()) camera = "camera" + std::to_string(i);
    cams[i].image_name = cams.size() == 1 ? stem + ".png" : stem + "_" + camera + ".png";
    for (size_t k = 0; k < i; ++k)
      if (cams[k].image_name == cams[i].image_name) {
        cams[i].image_name = stem + "_" + camera + "_" + std::to_string(i) + ".png";
        break;
      }
  }
}

ImportedScene Importer::run(int default_width, bool use_extras) {
  // Only rtconvert's own glTF 2.0 files matter here; anything else (glTF 1.0, a broken
  // file) is left to Assimp, whose message then names the problem.
  try {
    gltf_ = read_gltf_json(file_);
  } catch (const ConvertError&) {
    gltf_ = nullptr;
  }
  const json* scene_extras = nullptr;
  if (gltf_.is_object() && gltf_.contains("scenes") && gltf_["scenes"].is_array()) {
    size_t at = gltf_.contains("scene") && gltf_["scene"].is_number_unsigned()
                    ? gltf_["scene"].get<size_t>()
                    : 0;
    if (at < gltf_["scenes"].size()) {
      json& sc = gltf_["scenes"][at];  // A reference into gltf_, which outlives the import.
      if (sc.is_object() && sc.contains("extras") && sc["extras"].is_object() &&
          sc["extras"].contains(kExtrasKey))
        scene_extras = &sc["extras"][kExtrasKey];
    }
  }
  course_ = use_extras && scene_extras != nullptr;

  Assimp::Importer importer;
  // rtconvert's own files keep their vertices as written (bit-exact round trip); others are
  // welded where position and normal agree (texture seams do not split a smooth mesh).
  unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  if (!course_) {
    // Texture coordinates stay for textured meshes; mesh_of welds the others again.
    flags |= aiProcess_JoinIdenticalVertices | aiProcess_RemoveComponent;
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                                aiComponent_COLORS | aiComponent_TANGENTS_AND_BITANGENTS);
  }
  ai_ = importer.ReadFile(file_, flags);
  if (!ai_) throw ConvertError(file_ + ": " + importer.GetErrorString());
  if (ai_->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
    throw ConvertError(
        file_ + ": no meshes (the file holds only cameras, lights, animations or a skeleton)");
  if (ai_->HasAnimations())
    report_.warn(file_ + ": " + std::to_string(ai_->mNumAnimations) +
                 " animations ignored (the scene is taken at rest)");

  if (std::filesystem::path(file_).extension() == ".obj" ||
      std::filesystem::path(file_).extension() == ".OBJ")
    warn_missing_material_libraries(file_, report_);
  rt::SceneDesc& s = out_.scene;
  s.file = file_;
  // glTF's colour textures are sRGB by its specification; OBJ and FBX say nothing, and
  // their maps are used as stored, as the course's are.
  textures_ = std::make_unique<TextureImporter>(*ai_, file_, gltf_.is_object(), out_, report_);
  if (course_) {
    settings_from_json(*scene_extras, s);
    textures_from_json(*scene_extras, gltf_, file_, out_);
    for (const json& a : scene_extras->value("areaLights", json::array()))
      s.area_lights.push_back(area_light_from_json(a));
    for (const json& l : scene_extras->value("lights", json::array()))
      s.lights.push_back(device_light_from_json(l));
    std::map<int, Material> by_index;
    // Materials by name, in the exporter's order: it names its i-th material material<i>. Another
    // tool may have dropped some (a gap, filled below), so the numbers may pass the count, but not
    // the bound here: any other name would throw from std::stoi or make billions of default
    // materials.
    constexpr size_t kMaxMaterials = 1 << 16;
    for (const json& m : gltf_.value("materials", json::array()))
      if (m.contains("extras") && m["extras"].contains(kExtrasKey)) {
        std::string n = m.value("name", "");
        if (n.rfind("material", 0) != 0) continue;
        // material<i>, or material<i>_textured<k>: a textured object's copy of material i.
        size_t end = 8;
        while (end < n.size() && std::isdigit(static_cast<unsigned char>(n[end]))) ++end;
        const std::string digits = n.substr(8, end - 8);
        const bool copy_of = end == n.size() || n.compare(end, 9, "_textured") == 0;
        size_t index = kMaxMaterials;
        if (!digits.empty() && digits.size() <= 5 && copy_of) index = std::stoul(digits);
        if (index >= kMaxMaterials)
          throw ConvertError(file_ + ": glTF material '" + n +
                             "' has course extras but is not named material0 to material" +
                             std::to_string(kMaxMaterials - 1));
        by_index[static_cast<int>(index)] = material_from_json(m["extras"][kExtrasKey]);
      }
    // A material another tool dropped leaves a gap: a default takes its place.
    int count = by_index.empty() ? 0 : by_index.rbegin()->first + 1;
    for (int i = 0; i < count; ++i) {
      if (!by_index.count(i))
        report_.warn(file_ + ": material" + std::to_string(i) + " is missing: a default one");
      Material grey{};
      grey.diffuse = make_float3(0.8f, 0.8f, 0.8f);
      grey.phong_exponent = grey.refraction_index = 1;
      s.materials.push_back(by_index.count(i) ? by_index[i] : grey);
    }
    // Pointers into gltf_ itself (value() would return a copy).
    if (gltf_.contains("nodes"))
      for (const json& n : gltf_["nodes"])
        if (n.contains("extras") && n["extras"].contains(kExtrasKey))
          node_extras_[n.value("name", "")] = &n["extras"][kExtrasKey];
  }
  walk(ai_->mRootNode, Mat4());
  if (smooth_guessed_)
    report_.warn(file_ + ": " + std::to_string(smooth_guessed_) +
                 " meshes with smooth vertex normals: shadingMode=\"smooth\" (area-weighted "
                 "normals replace the file's)");
  if (s.objects.empty() && s.area_lights.empty())
    throw ConvertError(file_ + ": no triangle geometry to render");
  if (course_) {
    for (const json& c : gltf_.value("cameras", json::array()))
      if (c.contains("extras") && c["extras"].contains(kExtrasKey))
        s.cameras.push_back(camera_from_json(c["extras"][kExtrasKey]));
    if (gltf_.contains("extensions") && gltf_["extensions"].contains("KHR_lights_punctual"))
      for (const json& l :
           gltf_["extensions"]["KHR_lights_punctual"].value("lights", json::array()))
        if (l.contains("extras") && l["extras"].contains(kExtrasKey))
          s.point_lights.push_back(point_light_from_json(l["extras"][kExtrasKey]));
  } else {
    import_cameras(*ai_, file_, gltf_.is_object(), default_width, s, report_);
    import_lights(*ai_, file_, gltf_.is_object(), s, report_);
  }
  add_defaults(file_, default_width, s, report_);
  if (!course_) name_images();
  return std::move(out_);
}

}  // namespace

ImportedScene import_with_assimp(const std::string& path, int default_width, bool use_extras,
                                 Report& report) {
  try {
    return Importer(path, report).run(default_width, use_extras);
  } catch (const json::exception& e) {
    throw ConvertError(path + ": glTF extras." + kExtrasKey + " malformed: " + e.what());
  } catch (const ConvertError& e) {
    // The extras' readers do not know the file: their messages start with "extras".
    if (std::string(e.what()).rfind("extras", 0) != 0) throw;
    throw ConvertError(path + ": glTF " + e.what());
  }
}

}  // namespace rtconvert
