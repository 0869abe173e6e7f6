// Lights: ambient, point, area, directional, spot (environment: environment.cpp).
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
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

void Loader::read_lights(const XMLElement* scene) {
  const XMLElement* lights = child(scene, "Lights", false);
  if (!lights) return;
  for (auto* l = lights->FirstChildElement(); l; l = l->NextSiblingElement()) {
    std::string name = l->Name();
    auto non_negative = [&](const XMLElement* e) {
      Vec3d v = vec3(e);
      if (v.x < 0 || v.y < 0 || v.z < 0) fail_value(e, "is negative (light values must be >= 0)");
      return v;
    };
    if (name == "AmbientLight") {
      scene_.ambient = non_negative(l);
    } else if (name == "PointLight") {
      PointLight p{};
      p.position = vec3(child(l, "Position", true));
      p.intensity = to_float3(non_negative(child(l, "Intensity", true)));
      scene_.point_lights.push_back(p);
    } else if (name == "AreaLight") {
      AreaLight a{};
      Vec3d pos = vec3(child(l, "Position", true));
      Vec3d e1, e2, radiance;
      if (child(l, "EdgeVector1", false)) {
        // The older dialect: a parallelogram with a corner at Position.
        e1 = vec3(child(l, "EdgeVector1", true));
        e2 = vec3(child(l, "EdgeVector2", true));
        radiance = non_negative(child(l, "Intensity", true));
      } else {
        Vec3d n = normalize(nonzero(child(l, "Normal", true), vec3(child(l, "Normal", true))));
        const XMLElement* size_e = child(l, "Size", true);
        double size = number(size_e);
        if (!(size > 0)) fail_value(size_e, "must be positive");
        radiance = non_negative(child(l, "Radiance", true));
        // Any orthonormal pair spanning the plane gives the same uniform square.
        Vec3d helper = std::fabs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
        Vec3d u = normalize(cross(n, helper)), v = cross(n, u);
        e1 = u * size;
        e2 = v * size;
        pos = pos - e1 * 0.5 - e2 * 0.5;
      }
      Vec3d normal = cross(e1, e2);
      if (length(normal) == 0) fail(l, "degenerate light: zero area");
      a.corner = pos;
      a.edge1 = to_float3(e1);
      a.edge2 = to_float3(e2);
      a.normal = to_float3(normalize(normal));
      a.radiance = to_float3(radiance);
      a.area = static_cast<float>(length(normal));
      scene_.area_lights.push_back(a);
    } else if (name == "DirectionalLight") {
      Light d{};
      d.type = RT_LIGHT_DIRECTIONAL;
      const XMLElement* dir = child(l, "Direction", true);
      d.normal = to_float3(normalize(nonzero(dir, vec3(dir))));
      d.emission = to_float3(non_negative(child(l, "Radiance", true)));
      scene_.lights.push_back(d);  // prepare_camera sets its reach from the scene's bounds.
    } else if (name == "SpotLight") {
      Light s{};
      s.type = RT_LIGHT_SPOT;
      s.position = to_float3(vec3(child(l, "Position", true)));
      const XMLElement* dir = child(l, "Direction", true);
      s.normal = to_float3(normalize(nonzero(dir, vec3(dir))));
      s.emission = to_float3(non_negative(child(l, "Intensity", true)));
      const XMLElement* cov = child(l, "CoverageAngle", true);
      const XMLElement* fall = child(l, "FalloffAngle", true);
      double coverage = number(cov), falloff = number(fall);
      if (!(coverage > 0 && coverage <= 360)) fail_value(cov, "must lie in (0, 360] degrees");
      if (!(falloff >= 0 && falloff <= coverage))
        fail_value(fall, "must lie in [0, CoverageAngle] degrees");
      RT_SPOT_COS_COVERAGE(&s) = static_cast<float>(std::cos(coverage * M_PI / 360.0));
      RT_SPOT_COS_FALLOFF(&s) = static_cast<float>(std::cos(falloff * M_PI / 360.0));
      scene_.lights.push_back(s);
    } else if (name == "SphericalDirectionalLight") {
      read_environment_light(l, scene);
    }  // Other kinds were reported by check_scene_structure.
  }
}

}  // namespace loader
}  // namespace rt
