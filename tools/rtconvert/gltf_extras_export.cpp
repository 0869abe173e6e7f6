// Completes the .glb that Assimp wrote: glTF cameras and KHR_lights_punctual point lights
// (what viewers show), glTF's own material model (pbrMetallicRoughness, transmission, ior,
// volume), and under extras.ceng795 the course's exact values, which the importer prefers.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "course_extras.h"
#include "gltf_export.h"

namespace rtconvert {
namespace {

using rt::Vec3d;

double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }

json base_colour(float3 c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z), 1.0}; }

// glTF's metallic-roughness view of a course material, for viewers; the importer reads
// the extras instead. Blinn-Phong exponent n maps to roughness through the Beckmann
// correspondence n = 2 / alpha^2 - 2 with alpha = roughness^2.
void native_material(json& g, const Material& m) {
  json pbr;
  double rough = std::sqrt(std::sqrt(2.0 / (std::max(0.0f, m.phong_exponent) + 2.0)));
  switch (m.type) {
    case RT_MATERIAL_MIRROR:
      pbr = {{"baseColorFactor", base_colour(m.mirror)},
             {"metallicFactor", 1.0},
             {"roughnessFactor", clamp01(m.roughness)}};
      break;
    case RT_MATERIAL_CONDUCTOR:
      pbr = {{"baseColorFactor", base_colour(m.mirror)},
             {"metallicFactor", 1.0},
             {"roughnessFactor", clamp01(m.roughness)}};
      break;
    case RT_MATERIAL_DIELECTRIC: {
      pbr = {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}},
             {"metallicFactor", 0.0},
             {"roughnessFactor", clamp01(m.roughness)}};
      // Beer's law: attenuationColor is the transmittance over attenuationDistance = 1.
      json att = {std::exp(-m.absorption.x), std::exp(-m.absorption.y), std::exp(-m.absorption.z)};
      g["extensions"] = {
          {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
          {"KHR_materials_ior", {{"ior", m.refraction_index}}},
          {"KHR_materials_volume",
           {{"thicknessFactor", 1.0}, {"attenuationDistance", 1.0}, {"attenuationColor", att}}}};
      break;
    }
    default:
      pbr = {{"baseColorFactor", base_colour(m.diffuse)},
             {"metallicFactor", 0.0},
             {"roughnessFactor", rough}};
  }
  g["pbrMetallicRoughness"] = pbr;
}

// glTF cameras look down -Z with +Y up; the node's matrix (column-major) places them.
json camera_node(const rt::CameraDesc& c, size_t index) {
  Vec3d w = normalize(c.gaze) * -1.0;
  Vec3d u = normalize(cross(c.up, w));
  Vec3d v = cross(w, u);
  return {{"name", "camera" + std::to_string(index)},
          {"camera", index},
          {"matrix",
           {u.x, u.y, u.z, 0, v.x, v.y, v.z, 0, w.x, w.y, w.z, 0, c.position.x, c.position.y,
            c.position.z, 1}}};
}

int index_by_name(const json& list, const std::string& name) {
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].value("name", "") == name) return static_cast<int>(i);
  return -1;
}

void add_extension_used(json& g, const std::string& name) {
  json& used = g["extensionsUsed"];
  if (!used.is_array()) used = json::array();
  if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
}

// The image files, embedded in the .glb (a .glb is one self-contained file).
std::vector<std::string> image_bytes(const std::vector<ImageFile>& images) {
  std::vector<std::string> out;
  for (const ImageFile& f : images) {
    if (!f.bytes.empty()) {
      out.push_back(f.bytes);
      continue;
    }
    std::ifstream in(f.path, std::ios::binary);
    if (!in) throw ConvertError(f.path + ": cannot read the texture image");
    out.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return out;
}

// glTF images (what viewers show) hold PNG and JPEG only; "" for the others (HDR maps).
std::string mime_type(const std::string& bytes) {
  if (bytes.size() > 4 && bytes.compare(1, 3, "PNG") == 0) return "image/png";
  if (bytes.size() > 3 && static_cast<unsigned char>(bytes[0]) == 0xFF &&
      static_cast<unsigned char>(bytes[1]) == 0xD8)
    return "image/jpeg";
  return "";
}

// Textured material variants: glTF's baseColorTexture shows a replace_kd map in viewers
// (baseColorFactor 255 / Normalizer, as the course divides the image by it).
void native_textures(json& g, const rt::SceneDesc& s, const std::map<int, int>& gltf_image) {
  const std::vector<MaterialVariant> variants = material_variants(s);
  std::map<int, int> texture_of_image;  // Course image -> glTF texture.
  for (size_t i = s.materials.size(); i < variants.size(); ++i) {
    int at = index_by_name(g["materials"], variant_name(variants, i));
    int t = image_map(s, variants[i].textures, RT_DECAL_REPLACE_KD);
    if (at < 0 || t < 0 || !gltf_image.count(s.textures[t].image)) continue;
    const int image = s.textures[t].image;
    if (!texture_of_image.count(image)) {
      texture_of_image[image] = static_cast<int>(g["textures"].size());
      g["textures"].push_back({{"source", gltf_image.at(image)}});
    }
    json& pbr = g["materials"][at]["pbrMetallicRoughness"];
    double k = std::min(1.0, 255.0 / s.textures[t].desc.normalizer);
    pbr["baseColorTexture"] = {{"index", texture_of_image[image]}};
    pbr["baseColorFactor"] = {k, k, k, 1.0};
  }
}

}  // namespace

void add_course_data_to_glb(const rt::SceneDesc& s, const std::string& path,
                            const std::vector<ImageFile>& images, Report& report) {
  json g = read_gltf_json(path);
  json& scene = g["scenes"][g.value("scene", 0)];
  scene["extras"][kExtrasKey] = settings_to_json(s);
  scene["extras"][kExtrasKey]["version"] = 1;
  // Every image goes into the binary chunk as a bufferView (rewrite_glb_json appends
  // them after Assimp's); PNG and JPEG ones are glTF images too.
  const std::vector<std::string> blobs = image_bytes(images);
  std::map<int, int> gltf_image;  // Course image -> glTF image.
  for (size_t k = 0; k < blobs.size(); ++k) {
    const size_t view = g["bufferViews"].size() + k;
    const std::filesystem::path file(images[k].bytes.empty() ? images[k].path : images[k].name);
    scene["extras"][kExtrasKey]["images"].push_back(
        {{"bufferView", view}, {"name", file.filename().string()}, {"degamma", images[k].degamma}});
    if (mime_type(blobs[k]).empty()) continue;
    gltf_image[static_cast<int>(k)] = static_cast<int>(g["images"].size());
    g["images"].push_back(
        {{"bufferView", view}, {"mimeType", mime_type(blobs[k])}, {"name", file.stem().string()}});
  }
  for (const rt::TextureMapDesc& t : s.textures)
    scene["extras"][kExtrasKey]["textures"].push_back(
        texture_to_json(t, t.image >= 0 && images[t.image].degamma));
  scene["extras"][kExtrasKey]["backgroundTexture"] = s.background_texture;
  for (const Light& l : s.lights)
    if (l.type == RT_LIGHT_DIRECTIONAL || l.type == RT_LIGHT_SPOT)
      scene["extras"][kExtrasKey]["lights"].push_back(device_light_to_json(l));
  for (const AreaLight& a : s.area_lights)
    scene["extras"][kExtrasKey]["areaLights"].push_back(area_light_to_json(a));
  if (!s.area_lights.empty())
    report.warn(path + ": glTF has no area lights: " + std::to_string(s.area_lights.size()) +
                " written as emissive quads (visible, unlike the course's), exact in extras");
  // Emission above 1 needs KHR_materials_emissive_strength: the factor keeps the colour.
  for (size_t i = 0; i < s.area_lights.size(); ++i) {
    int at = index_by_name(g["materials"], area_light_name(i));
    if (at < 0) throw ConvertError(path + ": Assimp dropped material " + area_light_name(i));
    const float3 r = s.area_lights[i].radiance;
    double peak = std::max({r.x, r.y, r.z, 1e-30f});
    json& m = g["materials"][at];
    m.erase("extensions");
    m["pbrMetallicRoughness"] = {{"baseColorFactor", {0.0, 0.0, 0.0, 1.0}},
                                 {"metallicFactor", 0.0}};
    m["emissiveFactor"] = {r.x / peak, r.y / peak, r.z / peak};
    m["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = peak / kRadianceScale;
    m["doubleSided"] = true;
    int node = index_by_name(g["nodes"], area_light_name(i));
    if (node >= 0) g["nodes"][node]["extras"][kExtrasKey] = {{"kind", "areaLight"}, {"light", i}};
  }

  const std::vector<MaterialVariant> variants = material_variants(s);
  for (size_t i = 0; i < variants.size(); ++i) {
    int at = index_by_name(g["materials"], variant_name(variants, i));
    if (at < 0) continue;  // Assimp drops materials no mesh uses.
    json& m = g["materials"][at];
    m.erase("extensions");  // Assimp's guess (specular-glossiness) gives way to ours.
    native_material(m, s.materials[variants[i].material]);
    m["extras"][kExtrasKey] = material_to_json(s.materials[variants[i].material]);
  }
  native_textures(g, s, gltf_image);
  // Assimp lists extensions it did not use (volume, FB_ngon_encoding for our triangles);
  // the list is rebuilt from what the file holds.
  g.erase("extensionsUsed");
  for (const char* ext : {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume",
                          "KHR_materials_emissive_strength"})
    for (const json& m : g["materials"])
      if (m.contains("extensions") && m["extensions"].contains(ext)) add_extension_used(g, ext);

  for (size_t i = 0; i < s.objects.size(); ++i) {
    int at = index_by_name(g["nodes"], object_name(i));
    if (at < 0) throw ConvertError(path + ": Assimp dropped node " + object_name(i));
    const rt::ObjectDesc& o = s.objects[i];
    g["nodes"][at]["extras"][kExtrasKey] = {
        {"object", i},
        {"kind", o.kind == rt::ObjectDesc::kSphere ? "sphere" : "mesh"},
        {"mesh", o.mesh},
        {"smooth", o.kind == rt::ObjectDesc::kMesh && s.meshes[o.mesh].smooth},
        {"material", o.material},
        {"matrix", to_json(o.transform)},
        {"motionBlur", to_json(o.motion)},
        {"textures", o.textures},
        {"emits", o.emits},
        {"radiance", to_json(o.radiance)}};
  }
  int moving = 0;
  for (const auto& o : s.objects) moving += o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0;
  if (moving)
    report.warn(path + ": glTF has no motion blur: " + std::to_string(moving) +
                " objects keep their MotionBlur vector in extras only");

  for (size_t i = 0; i < s.cameras.size(); ++i) {
    const rt::CameraDesc& c = s.cameras[i];
    double half_h = std::max(std::fabs(c.top), std::fabs(c.bottom));
    json cam = {{"type", "perspective"},
                {"name", "camera" + std::to_string(i)},
                {"perspective",
                 {{"yfov", 2 * std::atan(half_h / c.near_distance)},
                  {"aspectRatio", (c.right - c.left) / (c.top - c.bottom)},
                  {"znear", c.near_distance * 1e-3}}},
                {"extras", {{kExtrasKey, camera_to_json(c)}}}};
    if (c.left != -c.right || c.bottom != -c.top)
      report.warn(path + ": camera " + std::to_string(i) +
                  ": off-centre near plane kept in extras; glTF viewers see a centred one");
    if (c.aperture > 0)
      report.warn(path + ": camera " + std::to_string(i) +
                  ": depth of field kept in extras only (glTF cameras are pinholes)");
    g["cameras"].push_back(cam);
    scene["nodes"].push_back(g["nodes"].size());
    g["nodes"].push_back(camera_node(c, i));
  }

  // Point lights: glTF's intensity is in candela, and a Lambertian surface of albedo 1 at
  // 1 m shows cd / pi, which is 255 on the course's scale; the exact value is in extras.
  json lights = json::array();
  for (size_t i = 0; i < s.point_lights.size(); ++i) {
    const PointLight& p = s.point_lights[i];
    double peak = std::max({p.intensity.x, p.intensity.y, p.intensity.z, 1e-30f});
    lights.push_back({{"type", "point"},
                      {"name", "light" + std::to_string(i)},
                      {"color", {p.intensity.x / peak, p.intensity.y / peak, p.intensity.z / peak}},
                      {"intensity", peak * M_PI / kRadianceScale},
                      {"extras", {{kExtrasKey, point_light_to_json(p)}}}});
    scene["nodes"].push_back(g["nodes"].size());
    g["nodes"].push_back({{"name", "light" + std::to_string(i)},
                          {"translation", to_json(p.position)},
                          {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
  }
  if (!lights.empty()) {
    g["extensions"]["KHR_lights_punctual"]["lights"] = lights;
    add_extension_used(g, "KHR_lights_punctual");
  }
  rewrite_glb_json(path, g, blobs);
}

}  // namespace rtconvert
