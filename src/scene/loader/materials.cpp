// BRDFs and materials.
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
#include "util/errors.h"
#include "image/read_ldr.h"
#include "scene/loader/loader.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/xml_text.h"

namespace rt {
namespace loader {

// <BRDFs> of hw6: each element names a model of cl/brdf.h; materials refer to it by id
// (Material BRDF="id") and take its exponent in place of PhongExponent.
void Loader::read_brdfs(const XMLElement* scene) {
  const XMLElement* list = child(scene, "BRDFs", false);
  for (auto* e = list ? list->FirstChildElement() : nullptr; e; e = e->NextSiblingElement()) {
    std::string name = e->Name();
    Material b{};
    if (name == "OriginalBlinnPhong")
      b.brdf = RT_BRDF_ORIGINAL_BLINN_PHONG;
    else if (name == "OriginalPhong")
      b.brdf = RT_BRDF_ORIGINAL_PHONG;
    else if (name == "ModifiedBlinnPhong")
      b.brdf = RT_BRDF_MODIFIED_BLINN_PHONG;
    else if (name == "ModifiedPhong")
      b.brdf = RT_BRDF_MODIFIED_PHONG;
    else if (name == "TorranceSparrow")
      b.brdf = RT_BRDF_TORRANCE_SPARROW;
    else
      fail(e, "unknown BRDF type");
    auto flag = [&](const char* attr) {
      const char* v = e->Attribute(attr);
      if (!v) return false;
      if (std::string(v) == "true") return true;
      if (std::string(v) == "false") return false;
      fail(e, std::string(attr) + "='" + shorten(v) + "' must be true or false");
    };
    if (flag("normalized")) b.brdf_flags |= RT_BRDF_NORMALIZED;
    if (flag("kdfresnel")) b.brdf_flags |= RT_BRDF_KD_FRESNEL;
    b.phong_exponent = static_cast<float>(child_number(e, "Exponent", 1));
    if (!(b.phong_exponent >= 0)) fail_value(child(e, "Exponent", true), "must not be negative");
    const char* id = e->Attribute("id");
    if (!id) fail(e, "missing id attribute");
    brdfs_[id] = b;
  }
}

void Loader::read_materials(const XMLElement* scene) {
  const XMLElement* mats = child(scene, "Materials", false);
  // Files of 2017-2019 have no type attribute; they mark glass with <Transparency> and
  // mirrors with MirrorReflectance alone. Later files ignore MirrorReflectance without
  // type="mirror" (the course's hw1 car scene relies on that).
  bool old_dialect = false;
  for (auto* e = mats ? mats->FirstChildElement("Material") : nullptr; e;
       e = e->NextSiblingElement("Material"))
    old_dialect = old_dialect || e->FirstChildElement("Transparency");
  for (auto* e = mats ? mats->FirstChildElement("Material") : nullptr; e;
       e = e->NextSiblingElement("Material")) {
    Material m{};
    m.ambient = to_float3(child_vec3(e, "AmbientReflectance", {}));
    m.diffuse = to_float3(child_vec3(e, "DiffuseReflectance", {}));
    m.specular = to_float3(child_vec3(e, "SpecularReflectance", {}));
    m.mirror = to_float3(child_vec3(e, "MirrorReflectance", {}));
    m.absorption = to_float3(child_vec3(e, "AbsorptionCoefficient", {}));
    m.phong_exponent = static_cast<float>(child_number(e, "PhongExponent", 1));
    m.refraction_index = static_cast<float>(child_number(e, "RefractionIndex", 1));
    m.absorption_index = static_cast<float>(child_number(e, "AbsorptionIndex", 0));
    m.roughness = static_cast<float>(child_number(e, "Roughness", 0));
    if (m.roughness < 0) fail_value(child(e, "Roughness", true), "must not be negative");
    if (!(m.refraction_index > 0))
      fail_value(child(e, "RefractionIndex", true), "must be positive");
    std::string type = e->Attribute("type") ? e->Attribute("type") : "";
    Vec3d transparency = child_vec3(e, "Transparency", {});
    if (type == "mirror") {
      m.type = RT_MATERIAL_MIRROR;
    } else if (type == "conductor") {
      m.type = RT_MATERIAL_CONDUCTOR;
    } else if (type == "dielectric") {
      m.type = RT_MATERIAL_DIELECTRIC;
    } else if (old_dialect && type.empty() && length(transparency) > 0) {
      m.type = RT_MATERIAL_DIELECTRIC;
    } else if (old_dialect && type.empty() &&
               (m.mirror.x > 0 || m.mirror.y > 0 || m.mirror.z > 0)) {
      m.type = RT_MATERIAL_MIRROR;
    } else if (!type.empty()) {
      warn(e, "unknown material type '" + type + "', treated as plain");
    }
    if (const char* brdf = e->Attribute("BRDF")) {
      auto it = brdfs_.find(brdf);
      if (it == brdfs_.end()) fail(e, std::string("BRDF='") + shorten(brdf) + "' names no BRDF");
      m.brdf = it->second.brdf;
      m.brdf_flags = it->second.brdf_flags;
      m.phong_exponent = it->second.phong_exponent;
    }
    // degamma="true": the reflectances were picked as display (gamma-encoded) colours, so
    // they are decoded with the course's gamma of 2.2 to linear values.
    if (const char* dg = e->Attribute("degamma"); dg && std::string(dg) == "true") {
      auto decode = [](float3 c) {
        return make_float3(std::pow(c.x, 2.2f), std::pow(c.y, 2.2f), std::pow(c.z, 2.2f));
      };
      m.ambient = decode(m.ambient);
      m.diffuse = decode(m.diffuse);
      m.specular = decode(m.specular);
    }
    const char* id = e->Attribute("id");
    material_ids_[id ? id : std::to_string(scene_.materials.size() + 1)] =
        static_cast<int>(scene_.materials.size());
    scene_.materials.push_back(m);
  }
}

}  // namespace loader
}  // namespace rt
