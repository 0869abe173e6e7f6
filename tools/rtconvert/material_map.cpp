#include "material_map.h"

#include <assimp/ObjMaterial.h>

#include <algorithm>
#include <cmath>

namespace rtconvert {
namespace {

struct Props {
  const aiMaterial& m;
  bool colour(const char* key, unsigned type, unsigned index, float3& out) const {
    aiColor4D c;
    if (m.Get(key, type, index, c) != AI_SUCCESS) return false;
    out = make_float3(c.r, c.g, c.b);
    return true;
  }
  bool number(const char* key, unsigned type, unsigned index, float& out) const {
    return m.Get(key, type, index, out) == AI_SUCCESS;
  }
  bool integer(const char* key, unsigned type, unsigned index, int& out) const {
    return m.Get(key, type, index, out) == AI_SUCCESS;
  }
};

float peak(float3 c) { return std::max({c.x, c.y, c.z}); }
float3 scale(float3 c, float s) { return make_float3(c.x * s, c.y * s, c.z * s); }

}  // namespace

MappedMaterial map_material(const aiMaterial& m, const std::string& file, Report& report) {
  Props p{m};
  MappedMaterial out;
  aiString name;
  out.name = m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS ? name.C_Str() : "";
  const std::string where = file + ": material '" + out.name + "': ";
  Material& r = out.material;
  r.refraction_index = 1;
  r.phong_exponent = 1;

  float3 diffuse = make_float3(0.8f, 0.8f, 0.8f), base{}, specular{}, ambient{}, emissive{},
         reflective{};
  bool has_diffuse = p.colour(AI_MATKEY_COLOR_DIFFUSE, diffuse);
  bool has_base = p.colour(AI_MATKEY_BASE_COLOR, base);
  bool has_specular = p.colour(AI_MATKEY_COLOR_SPECULAR, specular);
  p.colour(AI_MATKEY_COLOR_AMBIENT, ambient);
  bool has_reflective = p.colour(AI_MATKEY_COLOR_REFLECTIVE, reflective);
  float metallic = 0, roughness = 0.5f, transmission = 0, ior = 0, opacity = 1, shininess = 0,
        reflectivity = 0, shininess_strength = 1, emissive_strength = 1;
  bool has_metallic = p.number(AI_MATKEY_METALLIC_FACTOR, metallic);
  bool has_roughness = p.number(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
  p.number(AI_MATKEY_TRANSMISSION_FACTOR, transmission);
  p.number(AI_MATKEY_REFRACTI, ior);
  p.number(AI_MATKEY_OPACITY, opacity);
  bool has_shininess = p.number(AI_MATKEY_SHININESS, shininess) && shininess > 0;
  p.number(AI_MATKEY_SHININESS_STRENGTH, shininess_strength);
  p.number(AI_MATKEY_REFLECTIVITY, reflectivity);
  p.number(AI_MATKEY_EMISSIVE_INTENSITY, emissive_strength);
  int illum = -1;
  p.integer(AI_MATKEY_OBJ_ILLUM, illum);
  if (has_base && !has_diffuse) diffuse = base;
  if (has_base && has_metallic) diffuse = base;  // glTF: the base colour is the truth.

  // Textures: texture_import.cpp, once the material's type is known.
  if (p.colour(AI_MATKEY_COLOR_EMISSIVE, emissive) && peak(emissive) > 0)
    out.emission = scale(emissive, emissive_strength * kRadianceScale);

  const bool pbr = has_metallic || has_roughness;
  if (transmission > 0 || opacity < 1) {
    // Transmission (glTF) or partial opacity (OBJ d/Tr) -> glass.
    r.type = RT_MATERIAL_DIELECTRIC;
    r.refraction_index = ior > 1 ? ior : 1.5f;
    r.roughness = pbr ? roughness * roughness : 0;
    float3 att;
    float dist = 0;
    if (p.colour(AI_MATKEY_VOLUME_ATTENUATION_COLOR, att) &&
        p.number(AI_MATKEY_VOLUME_ATTENUATION_DISTANCE, dist) && dist > 0)
      r.absorption = make_float3(-std::log(std::max(att.x, 1e-6f)) / dist,
                                 -std::log(std::max(att.y, 1e-6f)) / dist,
                                 -std::log(std::max(att.z, 1e-6f)) / dist);
    if (transmission < 1 && opacity < 1)
      report.warn(where + "partial transparency (opacity " + std::to_string(opacity) +
                  ") mapped to a fully transmitting dielectric");
    if (!(ior > 1)) report.warn(where + "no index of refraction: 1.5 assumed");
  } else if (has_metallic && metallic >= 0.5f) {
    // A metal: complex index n = 0.2, k = 3 (reflectance about 0.92 at normal incidence,
    // as silver or aluminium) tinted by the base colour.
    r.type = RT_MATERIAL_CONDUCTOR;
    r.mirror = diffuse;
    r.refraction_index = 0.2f;
    r.absorption_index = 3.0f;
    r.roughness = roughness * roughness;
    if (metallic < 1 || roughness > 0)
      report.warn(where + "metallic " + std::to_string(metallic) + ", roughness " +
                  std::to_string(roughness) +
                  " approximated by a conductor (n 0.2, k 3) tinted by the base colour");
  } else if ((illum == 3 || illum == 5 || illum == 7) ||
             (has_reflective && reflectivity > 0 && peak(reflective) > 0)) {
    // OBJ's illum 3/5/7 (ray-traced reflection) or a reflective colour: a mirror.
    r.type = RT_MATERIAL_MIRROR;
    r.mirror = has_reflective && reflectivity > 0 ? scale(reflective, reflectivity) : specular;
    r.diffuse = diffuse;
  } else {
    r.diffuse = pbr ? scale(diffuse, 1 - metallic) : diffuse;
  }
  if (r.type == RT_MATERIAL_PLAIN || r.type == RT_MATERIAL_MIRROR) {
    if (has_specular && !pbr) {
      r.specular = scale(specular, shininess_strength);
      r.phong_exponent = has_shininess ? shininess : 1;
    } else if (pbr) {
      // Beckmann correspondence: exponent 2 / alpha^2 - 2 with alpha = roughness^2; the
      // specular colour fades with roughness as the lobe spreads.
      float a = std::max(roughness * roughness, 0.03f);
      r.phong_exponent = std::max(1.0f, 2 / (a * a) - 2);
      float s = 0.5f * (1 - roughness) * (1 - roughness);
      r.specular = make_float3(s, s, s);
      report.warn(where + "metallic-roughness (roughness " + std::to_string(roughness) +
                  ") approximated by Blinn-Phong, exponent " + std::to_string(r.phong_exponent));
    } else if (has_shininess) {
      r.phong_exponent = shininess;
    }
    r.ambient = ambient;
  }
  return out;
}

}  // namespace rtconvert
