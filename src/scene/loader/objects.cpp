// Transformations, vertex data and objects: spheres, triangles, meshes, instances.
#include <tinyxml2.h>

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "cl/material/brdf.h"
#include "image/read_ldr.h"
#include "scene/loader/loader.h"
#include "scene/loader/shared_ids.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

void Loader::read_transformations(const XMLElement* scene) {
  const XMLElement* ts = child(scene, "Transformations", false);
  for (auto* e = ts ? ts->FirstChildElement() : nullptr; e; e = e->NextSiblingElement()) {
    std::string name = e->Name();
    const char* id = e->Attribute("id");
    if (!id) fail(e, "missing id attribute");
    if (name == "Translation") {
      transforms_[std::string("t") + id] = Mat4::translation(vec3(e));
    } else if (name == "Scaling") {
      Vec3d s = vec3(e);
      if (s.x == 0 || s.y == 0 || s.z == 0)
        fail_value(e, "has a zero scale: the transform is singular");
      transforms_[std::string("s") + id] = Mat4::scaling(s);
    } else if (name == "Rotation") {
      auto v = numbers(e, 4, 4);
      Vec3d axis{v[1], v[2], v[3]};
      nonzero(e, axis, "has a zero-length rotation axis");
      transforms_[std::string("r") + id] = Mat4::rotation(v[0], axis);
    } else if (name == "Composite") {
      auto v = numbers(e, 16, 16);
      Mat4 m;
      for (int i = 0; i < 16; ++i) m.m[i] = v[i];
      // Only affine matrices are supported: a projective last row would be silently dropped.
      if (v[12] != 0 || v[13] != 0 || v[14] != 0 || v[15] != 1)
        fail(e, "last row '" + fmt(v[12]) + " " + fmt(v[13]) + " " + fmt(v[14]) + " " + fmt(v[15]) +
                    "' must be 0 0 0 1 (only affine transformations are supported)");
      transforms_[std::string("c") + id] = m;
    }  // Other kinds were reported by check_scene_structure.
  }
}

void Loader::read_vertices(const XMLElement* scene) {
  const XMLElement* vd = child(scene, "VertexData", false);
  if (!vd) return;
  auto v = data_numbers(vd, 3, "vertex", false);
  if (v.size() % 3 != 0) fail(vd, std::to_string(v.size()) + " numbers is not a multiple of 3");
  for (size_t i = 0; i + 2 < v.size(); i += 3) vertices_.push_back({v[i], v[i + 1], v[i + 2]});
}

int Loader::material_of(const XMLElement* e) const {
  const XMLElement* m = child(e, "Material", true);
  std::string id = text_of(m);
  id.erase(0, id.find_first_not_of(" \t\r\n"));
  id.erase(id.find_last_not_of(" \t\r\n") + 1);
  auto it = material_ids_.find(id);
  if (it == material_ids_.end()) fail(m, "no material with id '" + shorten(id) + "'");
  return it->second;
}

Mat4 Loader::transform_of(const XMLElement* e) const {
  Mat4 m;
  const XMLElement* t = child(e, "Transformations", false);
  if (!t) return m;
  std::istringstream in(text_of(t));
  std::string ref;
  // Each listed transformation applies after the ones before it.
  while (in >> ref) {
    auto it = transforms_.find(ref);
    if (it == transforms_.end()) fail(t, "no transformation '" + shorten(ref) + "'");
    m = it->second * m;
  }
  bool ok;
  m.affine_inverse(&ok);
  if (!ok) fail_value(t, "composes to a singular transformation");
  return m;
}

Vec3d Loader::motion_of(const XMLElement* e) const { return child_vec3(e, "MotionBlur", {}); }

// Checks in double before any conversion, so 1e30 or -1e300 cannot overflow a long. The
// message gives the range in the file's own base (1, or 0 with ZeroBasedIndexing).
int Loader::vertex_index(const XMLElement* e, double index, long offset) const {
  if (index != std::floor(index))
    fail(e, "vertex index '" + fmt(index) + "' is not a whole number");
  const int base = index_base();
  double g = index + static_cast<double>(offset);
  if (!(g >= base && g < static_cast<double>(vertices_.size()) + base))
    fail(e, "vertex index " + fmt(index) +
                (offset ? " + vertexOffset " + std::to_string(offset) + " = " + fmt(g) : "") +
                " out of range [" + std::to_string(base) + ", " +
                std::to_string(static_cast<long>(vertices_.size()) - 1 + base) + "]" +
                (zero_based_ ? " (ZeroBasedIndexing)" : ""));
  return static_cast<int>(g) - base;
}

// Builds a mesh from inline indices into VertexData or from a PLY file. Degenerate
// triangles (zero area) are dropped and counted.
int Loader::add_mesh_from_faces(const XMLElement* obj, const XMLElement* faces, bool smooth,
                                bool uvs) {
  MeshDesc mesh;
  mesh.element = describe(obj);
  mesh.smooth = smooth;
  if (faces->Attribute("plyFile") && faces->Attribute("binaryFile"))
    fail(faces, "has both plyFile and binaryFile: only one source is allowed");
  if (const char* ply = faces->Attribute("plyFile")) {
    std::filesystem::path p(ply);
    if (p.is_relative()) p = std::filesystem::path(file_).parent_path() / p;
    PlyMesh pm;
    try {
      scene_.inputs.push_back(p.string());
      pm = read_ply(p.string());
    } catch (const InputError& err) {
      fail_file(faces, "plyFile", p.string(), err);
    }
    for (auto& v : pm.positions) mesh.positions.push_back({v[0], v[1], v[2]});
    mesh.triangles = pm.triangles;
    for (auto& t : pm.uvs) mesh.uvs.push_back({t[0], t[1]});
  } else {
    auto idx = data_numbers(faces, 3, "triangle", true, 3);
    if (idx.size() % 3 != 0)
      fail(faces, std::to_string(idx.size()) + " indices is not a multiple of 3");
    int offset = 0;
    if (faces->Attribute("vertexOffset") &&
        faces->QueryIntAttribute("vertexOffset", &offset) != tinyxml2::XML_SUCCESS)
      fail(faces, "vertexOffset '" + shorten(faces->Attribute("vertexOffset")) +
                      "' is not a whole number");
    // TexCoordData pairs with VertexData entry for entry; textureOffset shifts the
    // texture-coordinate indices as vertexOffset shifts the vertex indices.
    int tex_offset = 0;
    if (faces->Attribute("textureOffset") &&
        faces->QueryIntAttribute("textureOffset", &tex_offset) != tinyxml2::XML_SUCCESS)
      fail(faces, "textureOffset '" + shorten(faces->Attribute("textureOffset")) +
                      "' is not a whole number");
    // Only the vertices the mesh uses are copied, renumbered in order of first use.
    std::map<std::pair<int, int>, int> remap;
    for (size_t i = 0; i < idx.size(); i += 3) {
      std::array<int, 3> tri;
      for (int k = 0; k < 3; ++k) {
        int g = vertex_index(faces, idx[i + k], offset);
        int t = -1;
        if (uvs) {
          const int base = index_base();
          double tg = idx[i + k] + static_cast<double>(tex_offset);
          if (!(tg >= base && tg < static_cast<double>(texcoords_.size()) + base))
            fail(faces, "texture coordinate index " + fmt(idx[i + k]) +
                            (tex_offset ? " + textureOffset " + std::to_string(tex_offset) : "") +
                            " out of range [" + std::to_string(base) + ", " +
                            std::to_string(static_cast<long>(texcoords_.size()) - 1 + base) +
                            "] of TexCoordData" + (zero_based_ ? " (ZeroBasedIndexing)" : ""));
          t = static_cast<int>(tg) - base;
        }
        auto [it, inserted] =
            remap.emplace(std::make_pair(g, t), static_cast<int>(mesh.positions.size()));
        if (inserted) {
          mesh.positions.push_back(vertices_[g]);
          if (uvs) mesh.uvs.push_back(texcoords_[t]);
        }
        tri[k] = it->second;
      }
      mesh.triangles.push_back(tri);
    }
  }
  std::vector<std::array<int, 3>> kept;
  for (auto& t : mesh.triangles) {
    Vec3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    if (length(cross(b - a, c - a)) > 0)
      kept.push_back(t);
    else
      ++scene_.degenerate_triangles;
  }
  mesh.triangles.swap(kept);
  scene_.meshes.push_back(std::move(mesh));
  return static_cast<int>(scene_.meshes.size()) - 1;
}

// An object light's Radiance: three non-negative numbers.
Vec3d Loader::radiance_of(const XMLElement* e) const {
  const XMLElement* r = child(e, "Radiance", true);
  Vec3d v = vec3(r);
  if (!(v.x >= 0 && v.y >= 0 && v.z >= 0)) fail_value(r, "is negative (light values must be >= 0)");
  return v;
}

void Loader::read_objects(const XMLElement* scene) {
  const XMLElement* objs = child(scene, "Objects", false);
  for (auto* e = objs ? objs->FirstChildElement() : nullptr; e; e = e->NextSiblingElement()) {
    std::string name = e->Name();
    ObjectDesc o;
    o.element = describe(e);
    const char* id = e->Attribute("id");
    std::string key = id ? id : "";
    // LightMesh and LightSphere are a Mesh and a Sphere that also emit (hw6).
    if (name == "LightMesh" || name == "LightSphere") {
      o.emits = true;
      o.radiance = radiance_of(e);
    }
    if (name == "Mesh" || name == "Triangle" || name == "LightMesh") {
      o.material = material_of(e);
      const char* mode = e->Attribute("shadingMode");
      bool smooth = mode && std::string(mode) == "smooth";
      o.textures = textures_of(e);
      o.mesh = add_mesh_from_faces(e, child(e, name == "Triangle" ? "Indices" : "Faces", true),
                                   smooth, !o.textures.empty() && !texcoords_.empty());
      o.transform = transform_of(e);
      o.motion = motion_of(e);
      if (name == "Mesh") mesh_objects_[key] = static_cast<int>(scene_.objects.size());
      if (name == "LightMesh") light_mesh_objects_[key] = static_cast<int>(scene_.objects.size());
    } else if (name == "MeshInstance") {
      const char* base_id = e->Attribute("baseMeshId");
      if (!base_id) fail(e, "missing baseMeshId");
      // Older files reuse mesh ids for instances: the kinds are looked up in the order of
      // the shared-id table (a Mesh with the id wins). A LightMesh's instances are lights
      // too, each with its own transform.
      const std::map<std::string, const std::map<std::string, int>*> by_kind = {
          {"Mesh", &mesh_objects_},
          {"MeshInstance", &instance_objects_},
          {"LightMesh", &light_mesh_objects_}};
      int base_index = -1;
      for (const std::string& kind : shared_ids_of("Objects", "MeshInstance")->kinds) {
        const std::map<std::string, int>* ids = by_kind.at(kind);
        auto it = ids->find(base_id);
        if (it != ids->end()) {
          base_index = it->second;
          break;
        }
      }
      if (base_index < 0)
        fail(e, std::string("baseMeshId '") + shorten(base_id) +
                    "' names no earlier Mesh, MeshInstance or LightMesh");
      const ObjectDesc& base = scene_.objects[base_index];
      o.mesh = base.mesh;
      o.material = child(e, "Material", false) ? material_of(e) : base.material;
      o.textures = child(e, "Textures", false) ? textures_of(e) : base.textures;
      bool reset = false;
      if (e->Attribute("resetTransform") &&
          e->QueryBoolAttribute("resetTransform", &reset) != tinyxml2::XML_SUCCESS)
        fail(e, "resetTransform '" + shorten(e->Attribute("resetTransform")) +
                    "' is not true or false");
      o.transform = reset ? transform_of(e) : transform_of(e) * base.transform;
      o.motion = motion_of(e);
      o.emits = base.emits;
      o.radiance = base.radiance;
      // Object lights are sampled where they are at time 0 (as LightMesh's own MotionBlur).
      if (o.emits && length(o.motion) > 0)
        fail_value(child(e, "MotionBlur", true),
                   "is not supported on an instance of a LightMesh: the light would not move");
      instance_objects_[key] = static_cast<int>(scene_.objects.size());
    } else if (name == "Sphere" || name == "LightSphere") {
      o.kind = ObjectDesc::kSphere;
      o.material = material_of(e);
      o.textures = textures_of(e);
      const XMLElement* c = child(e, "Center", true);
      Vec3d centre = vertices_[vertex_index(c, number(c))];
      const XMLElement* r = child(e, "Radius", true);
      double radius = number(r);
      if (!(radius > 0)) fail_value(r, "must be positive");
      o.transform =
          transform_of(e) * Mat4::translation(centre) * Mat4::scaling({radius, radius, radius});
      o.motion = motion_of(e);
    } else {
      continue;  // Reported by check_scene_structure.
    }
    // Each factor was checked, but a product (radius 1e-120, a chain of instances) can
    // still underflow to a singular matrix, which the devices cannot invert.
    bool invertible;
    o.transform.affine_inverse(&invertible);
    if (!invertible) fail(e, "the object's composed transformation is singular");
    scene_.objects.push_back(o);
  }
}

}  // namespace loader
}  // namespace rt
