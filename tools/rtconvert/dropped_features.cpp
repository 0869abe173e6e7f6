// What each export format cannot carry, said in one warning line per feature, so that no
// conversion loses part of a scene silently. glTF keeps the course's values in extras and
// course XML is the course's own format, so most lines concern OBJ and pbrt-v4.
#include <string>

#include "convert.h"

namespace rtconvert {
namespace {

std::string count(int n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

void warn_dropped(const rt::SceneDesc& s, const std::string& path, const std::string& format,
                  Report& report) {
  const bool obj = format == "obj", pbrt = format == "pbrt", own = !obj && !pbrt;
  auto warn = [&](const std::string& what) { report.warn(path + ": " + what); };

  // Directional, spot and environment lights: no writer maps the device form back yet.
  int directional = 0, spot = 0, environment = 0;
  for (const Light& l : s.lights) {
    directional += l.type == RT_LIGHT_DIRECTIONAL;
    spot += l.type == RT_LIGHT_SPOT;
    environment += l.type == RT_LIGHT_ENVIRONMENT;
  }
  // glTF (extras) and XML keep directional and spot lights, pbrt approximates spots.
  if (obj && directional)
    warn("OBJ has no lights: " + count(directional, "DirectionalLight") + " lost");
  if (obj && spot) warn("OBJ has no lights: " + count(spot, "SpotLight") + " lost");
  if (pbrt && spot)
    warn(count(spot, "SpotLight") +
         " as pbrt's \"spot\", whose falloff between FalloffAngle "
         "and CoverageAngle is a smoothstep");
  if (environment)
    warn(count(environment, "SphericalDirectionalLight") + " (environment map) not converted");

  int emitters = 0, brdfs = 0, tonemaps = 0, path_tracing = 0;
  for (const auto& o : s.objects) emitters += o.emits;
  for (const Material& m : s.materials) brdfs += m.brdf != 0 || m.brdf_flags != 0;
  for (const auto& c : s.cameras) {
    tonemaps += c.tonemap;
    path_tracing += c.path_tracing;
  }
  if (obj && emitters)
    warn("OBJ has no object lights: " + count(emitters, "LightMesh/LightSphere") +
         " written as plain geometry, their Radiance lost");
  if (!own && brdfs)
    warn(count(brdfs, "material") + " with a BRDF of <BRDFs> written as " +
         (obj ? "Blinn-Phong (Kd Ks Ns)" : "pbrt's diffuse/conductor/dielectric"));
  if (obj && tonemaps)
    warn("OBJ has no cameras: " + count(tonemaps, "Tonemap") + " (Photographic) lost");
  if (obj && path_tracing)
    warn("OBJ has no cameras: " + count(path_tracing, "camera") +
         " with Renderer PathTracing and RendererParams lost");
  if (pbrt && !s.cameras.empty()) {
    const rt::CameraDesc& c = s.cameras[0];
    if (c.tonemap)
      warn("camera 0: Tonemap (Photographic, key " + std::to_string(c.tonemap_params.key) +
           ") not carried: pbrt writes the linear EXR");
    if (c.path_tracing && c.path_flags != (RT_FLAG_NEXT_EVENT | RT_FLAG_IMPORTANCE_SAMPLING |
                                           RT_FLAG_RUSSIAN_ROULETTE))
      warn(
          "camera 0: RendererParams not carried: pbrt's path integrator always uses "
          "next-event estimation, BSDF importance sampling and Russian roulette");
    if (!c.path_tracing)
      warn("camera 0: the course's recursive ray tracer becomes pbrt's path integrator");
    if (s.cameras.size() > 1)
      warn(count(static_cast<int>(s.cameras.size()) - 1, "camera") +
           " after the first not written: pbrt renders one camera per file");
  }

  // Textures: glTF and XML keep every map; OBJ's MTL has map_Kd and map_Ks for images.
  int kept = 0, procedural = 0, other = 0, background = s.background_texture >= 0;
  for (const auto& t : s.textures) {
    if (t.desc.decal == RT_DECAL_REPLACE_BACKGROUND) continue;
    const bool image = t.desc.type == RT_TEXTURE_IMAGE;
    const bool mtl =
        image && (t.desc.decal == RT_DECAL_REPLACE_KD || t.desc.decal == RT_DECAL_REPLACE_KS);
    procedural += !image;
    other += image && !mtl;
    kept += mtl;
  }
  if (pbrt && kept + other)
    warn(count(kept + other, "image TextureMap") + " and the texture coordinates not converted");
  if (obj && other)
    warn("MTL: " + count(other, "image TextureMap") +
         " with DecalMode blend_kd, bump_normal, replace_normal or replace_all not written "
         "(only replace_kd as map_Kd and replace_ks as map_Ks)");
  if (!own && procedural)
    warn(count(procedural, "perlin/checkerboard TextureMap") + " not converted (procedural)");
  if (!own && background) warn("the replace_background texture not converted");
}

}  // namespace rtconvert
