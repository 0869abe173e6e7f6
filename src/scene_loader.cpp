// Reads the METU CENG795 scene format (assignments 1-3 and the older dialects seen in
// the course's files) with tinyxml2.
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
#include "errors.h"
#include "image/read_ldr.h"
#include "ply.h"
#include "scene.h"
#include "scene_schema.h"
#include "xml_text.h"

namespace rt {
namespace {

using tinyxml2::XMLElement;

// A number as the file would write it: 3, -1.5, 1e+30.
std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

class Loader {
 public:
  Loader(std::string file, const LoadOptions& options)
      : file_(std::move(file)), options_(options) {}
  SceneDesc load();
  // Reads the scene from XML text already in memory; `file_` only names it and locates
  // the PLY files it refers to (the fuzzer feeds scenes this way).
  SceneDesc load_text(const std::string& xml);

 private:
  [[noreturn]] void fail(const XMLElement* e, const std::string& what) const {
    throw input_error(file_, e ? path_of(e) : std::string("Scene"), what);
  }
  // Quotes the element's text before `what`: "Radius: '-1' must be positive".
  [[noreturn]] void fail_value(const XMLElement* e, const std::string& what) const {
    fail(e, "'" + shorten(text_of(e)) + "' " + what);
  }

  std::vector<double> numbers(const XMLElement* e, size_t min_count, size_t max_count) const;
  double number(const XMLElement* e) const { return numbers(e, 1, 1)[0]; }
  Vec3d vec3(const XMLElement* e) const {
    auto v = numbers(e, 3, 3);
    return {v[0], v[1], v[2]};
  }
  const XMLElement* child(const XMLElement* e, const char* name, bool required) const;
  double child_number(const XMLElement* e, const char* name, double fallback) const;
  Vec3d child_vec3(const XMLElement* e, const char* name, Vec3d fallback) const;
  Vec3d nonzero(const XMLElement* e, Vec3d v, const char* what = "is a zero-length vector") const {
    if (length(v) == 0) fail_value(e, what);
    return v;
  }

  void read_cameras(const XMLElement* scene);
  void read_tonemap(const XMLElement* tm, CameraDesc* cam) const;
  void read_lights(const XMLElement* scene);
  void read_brdfs(const XMLElement* scene);
  void read_materials(const XMLElement* scene);
  void read_transformations(const XMLElement* scene);
  void read_vertices(const XMLElement* scene);
  void read_objects(const XMLElement* scene);
  void read_textures(const XMLElement* scene);
  TextureMapDesc read_texture_map(const XMLElement* e, const std::map<std::string, std::string>& images,
                                  std::map<std::string, int>& loaded);
  void read_texcoords(const XMLElement* scene);
  std::vector<int> textures_of(const XMLElement* e) const;
  void check_texture_coordinates() const;
  int material_of(const XMLElement* e) const;
  Mat4 transform_of(const XMLElement* e) const;
  Vec3d motion_of(const XMLElement* e) const;
  int vertex_index(const XMLElement* e, double one_based, long offset = 0) const;
  int add_mesh_from_faces(const XMLElement* obj, const XMLElement* faces, bool smooth, bool uvs);
  void warn(const XMLElement* e, const std::string& what) {
    warn(file_ + ": " + path_of(e) + ": " + what);
  }
  // With --strict, the first warning ends the load as an error.
  void warn(const std::string& line) {
    if (options_.strict) throw InputError(line + " [--strict: warnings are errors]");
    scene_.warnings.push_back(line);
  }
  SceneDesc read_document(const tinyxml2::XMLDocument& doc, tinyxml2::XMLError err);

  std::string file_;
  LoadOptions options_;
  SceneDesc scene_;
  std::map<std::string, int> material_ids_;
  std::map<std::string, Material> brdfs_;   // BRDF id -> the members a BRDF sets.
  std::map<std::string, Mat4> transforms_;  // Keyed "t1", "s2", "r3", "c4".
  std::vector<Vec3d> vertices_;
  std::vector<std::array<double, 2>> texcoords_;  // TexCoordData, one pair per vertex.
  std::map<std::string, int> texture_ids_;        // TextureMap id -> index.
  std::map<std::string, int> mesh_objects_;      // Mesh id -> object index.
  std::map<std::string, int> instance_objects_;  // MeshInstance id -> object index.
};

std::vector<double> Loader::numbers(const XMLElement* e, size_t min_count, size_t max_count) const {
  const std::string text = text_of(e);
  std::vector<double> out;
  const char* p = text.c_str();
  for (;;) {
    while (*p && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (!*p) break;
    const char* start = p;
    while (*p && !std::isspace(static_cast<unsigned char>(*p))) ++p;
    std::string token(start, p);
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || token.empty())
      fail(e, "not a number: '" + shorten(token) + "'");
    // Overflow gives inf; underflow (1e-400) is a representable tiny value, not an error.
    if (!std::isfinite(v)) fail(e, "not a finite number: '" + shorten(token) + "'");
    // The devices work in float: a larger value would turn into inf there.
    if (std::fabs(v) > FLT_MAX)
      fail(e, "'" + shorten(token) + "' is too large (beyond float range)");
    out.push_back(v);
  }
  if (out.size() < min_count || out.size() > max_count) {
    std::ostringstream s;
    s << "expected " << min_count;
    if (max_count != min_count)
      s << (max_count == SIZE_MAX ? " or more" : " to " + std::to_string(max_count));
    s << (max_count == 1 ? " number" : " numbers") << ", got " << out.size() << " ('"
      << shorten(text) << "')";
    fail(e, s.str());
  }
  return out;
}

const XMLElement* Loader::child(const XMLElement* e, const char* name, bool required) const {
  const XMLElement* c = e->FirstChildElement(name);
  if (!c && required) fail(e, std::string("missing <") + name + ">");
  return c;
}

double Loader::child_number(const XMLElement* e, const char* name, double fallback) const {
  const XMLElement* c = child(e, name, false);
  return c ? number(c) : fallback;
}

Vec3d Loader::child_vec3(const XMLElement* e, const char* name, Vec3d fallback) const {
  const XMLElement* c = child(e, name, false);
  return c ? vec3(c) : fallback;
}

void Loader::read_cameras(const XMLElement* scene) {
  // Files of 2017 put <Camera> directly under <Scene>, without <Cameras>.
  std::vector<const XMLElement*> list;
  for (auto* c = scene->FirstChildElement("Camera"); c; c = c->NextSiblingElement("Camera"))
    list.push_back(c);
  if (const XMLElement* cams = child(scene, "Cameras", false))
    for (auto* c = cams->FirstChildElement("Camera"); c; c = c->NextSiblingElement("Camera"))
      list.push_back(c);
  for (const XMLElement* c : list) {
    CameraDesc cam;
    cam.position = vec3(child(c, "Position", true));
    const XMLElement* up = child(c, "Up", true);
    cam.up = nonzero(up, vec3(up));
    cam.near_distance = number(child(c, "NearDistance", true));
    if (!(cam.near_distance > 0)) fail_value(child(c, "NearDistance", true), "must be positive");
    const char* type = c->Attribute("type");
    if (type && std::string(type) == "lookAt") {
      // hw6's lookAt cameras may give a <Gaze> direction instead of a <GazePoint>.
      if (!child(c, "GazePoint", false) && child(c, "Gaze", false)) {
        cam.gaze = nonzero(child(c, "Gaze", true), vec3(child(c, "Gaze", true)));
      } else {
        Vec3d target = vec3(child(c, "GazePoint", true));
        cam.gaze = nonzero(child(c, "GazePoint", true), target - cam.position,
                           "equals the camera Position: no gaze direction");
      }
      const XMLElement* fov = child(c, "FovY", true);
      double fovy = number(fov);
      if (!(fovy > 0 && fovy < 180)) fail_value(fov, "must lie in (0, 180) degrees");
      cam.top = cam.near_distance * std::tan(fovy * M_PI / 360.0);
      cam.bottom = -cam.top;
    } else {
      if (!child(c, "Gaze", false) && child(c, "GazePoint", false))
        fail(c, "missing <Gaze> (a camera with <GazePoint> needs type=\"lookAt\")");
      cam.gaze = nonzero(child(c, "Gaze", true), vec3(child(c, "Gaze", true)));
      // Some course files carry a fifth number (the near distance again); it is ignored.
      auto np = numbers(child(c, "NearPlane", true), 4, 5);
      cam.left = np[0];
      cam.right = np[1];
      cam.bottom = np[2];
      cam.top = np[3];
    }
    const XMLElement* res = child(c, "ImageResolution", true);
    auto r = numbers(res, 2, 2);
    if (r[0] < 1 || r[1] < 1 || r[0] > 32768 || r[1] > 32768 || r[0] != std::floor(r[0]) ||
        r[1] != std::floor(r[1]))
      fail_value(res, "width and height must be whole numbers in [1, 32768]");
    cam.width = static_cast<int>(r[0]);
    cam.height = static_cast<int>(r[1]);
    if (type && std::string(type) == "lookAt") {
      cam.right = cam.top * cam.width / cam.height;
      cam.left = -cam.right;
    }
    if (cam.left == cam.right || cam.bottom == cam.top) {
      if (const XMLElement* np = child(c, "NearPlane", false))
        fail_value(np, "is an empty image plane");
      fail(c, "empty image plane");
    }
    if (length(cross(cam.up, cam.gaze)) == 0) fail_value(up, "is parallel to the gaze direction");
    const XMLElement* name = child(c, "ImageName", true);
    std::string image = text_of(name);
    image.erase(0, image.find_first_not_of(" \t\r\n"));
    image.erase(image.find_last_not_of(" \t\r\n") + 1);
    if (image.empty()) fail(name, "empty image name");
    // Output stays inside --output-dir: no directories, no way out of it.
    if (image.find('/') != std::string::npos || image.find('\\') != std::string::npos ||
        image == "." || image == "..")
      fail_value(name, "must be a plain file name");
    cam.image_name = image;
    cam.element = path_of(name);
    if (const XMLElement* ns = child(c, "NumSamples", false)) {
      double n = number(ns);
      double root = std::round(std::sqrt(n));
      if (n < 1 || n != std::floor(n) || n > 1e6)
        fail_value(ns, "must be a whole number in [1, 1e6]");
      if (root * root != n)
        fail(ns, "'" + std::to_string(static_cast<long>(n)) +
                     "' is not a perfect square (jittered sampling needs n x n strata)");
      cam.samples = static_cast<int>(n);
    }
    cam.aperture = child_number(c, "ApertureSize", 0);
    if (cam.aperture < 0) fail_value(child(c, "ApertureSize", true), "must not be negative");
    cam.focus_distance = child_number(c, "FocusDistance", 1);
    if (cam.aperture > 0 && !(cam.focus_distance > 0))
      fail_value(child(c, "FocusDistance", true), "must be positive");
    if (const XMLElement* tm = child(c, "Tonemap", false)) read_tonemap(tm, &cam);
    scene_.cameras.push_back(cam);
  }
  if (scene_.cameras.empty()) fail(nullptr, "no <Camera>: nothing to render");
}

// The photographic operator's parameters (hw5/SPEC.txt); it is the only one the course
// defines, so any other <TMO> is an error rather than a silently different image.
void Loader::read_tonemap(const XMLElement* tm, CameraDesc* cam) const {
  const XMLElement* tmo = child(tm, "TMO", true);
  std::string name = shorten(text_of(tmo));
  if (name != "Photographic") fail_value(tmo, "is not a known operator (only Photographic)");
  auto opts = numbers(child(tm, "TMOOptions", true), 2, 2);
  if (!(opts[0] > 0)) fail_value(child(tm, "TMOOptions", true), "key value must be positive");
  if (!(opts[1] >= 0 && opts[1] < 100))
    fail_value(child(tm, "TMOOptions", true), "burn-out percentage must lie in [0, 100)");
  cam->tonemap = true;
  cam->tonemap_params.key = opts[0];
  cam->tonemap_params.burn_percent = opts[1];
  cam->tonemap_params.saturation = child_number(tm, "Saturation", 1.0);
  cam->tonemap_params.gamma = child_number(tm, "Gamma", 2.2);
  if (!(cam->tonemap_params.saturation >= 0))
    fail_value(child(tm, "Saturation", true), "must not be negative");
  if (!(cam->tonemap_params.gamma > 0)) fail_value(child(tm, "Gamma", true), "must be positive");
}

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
      p.position = to_float3(vec3(child(l, "Position", true)));
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
      a.corner = to_float3(pos);
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
      scene_.lights.push_back(d);  // flatten_scene sets param0 from the scene's bounds.
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
      s.param1 = static_cast<float>(std::cos(coverage * M_PI / 360.0));
      s.param0 = static_cast<float>(std::cos(falloff * M_PI / 360.0));
      scene_.lights.push_back(s);
    }  // Other kinds were reported by check_scene_structure.
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
  auto v = numbers(vd, 0, SIZE_MAX);
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

// Checks in double before any conversion, so 1e30 or -1e300 cannot overflow a long.
int Loader::vertex_index(const XMLElement* e, double one_based, long offset) const {
  if (one_based != std::floor(one_based))
    fail(e, "vertex index '" + fmt(one_based) + "' is not a whole number");
  double g = one_based + static_cast<double>(offset);
  if (!(g >= 1 && g <= static_cast<double>(vertices_.size())))
    fail(e, "vertex index " + fmt(one_based) +
                (offset ? " + vertexOffset " + std::to_string(offset) + " = " + fmt(g) : "") +
                " out of range [1, " + std::to_string(vertices_.size()) + "]");
  return static_cast<int>(g) - 1;
}

// Builds a mesh from inline indices into VertexData or from a PLY file. Degenerate
// triangles (zero area) are dropped and counted.
int Loader::add_mesh_from_faces(const XMLElement* obj, const XMLElement* faces, bool smooth,
                                bool uvs) {
  MeshDesc mesh;
  mesh.element = describe(obj);
  mesh.smooth = smooth;
  if (const char* ply = faces->Attribute("plyFile")) {
    std::filesystem::path p(ply);
    if (p.is_relative()) p = std::filesystem::path(file_).parent_path() / p;
    PlyMesh pm;
    try {
      scene_.inputs.push_back(p.string());
      pm = read_ply(p.string());
    } catch (const InputError& err) {
      // The PLY reader names the PLY file; add the scene file and the element.
      fail(faces, "plyFile '" + shorten(ply) + "': " + err.what());
    }
    for (auto& v : pm.positions) mesh.positions.push_back({v[0], v[1], v[2]});
    mesh.triangles = pm.triangles;
    for (auto& t : pm.uvs) mesh.uvs.push_back({t[0], t[1]});
  } else {
    auto idx = numbers(faces, 3, SIZE_MAX);
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
          double tg = idx[i + k] + static_cast<double>(tex_offset);
          if (!(tg >= 1 && tg <= static_cast<double>(texcoords_.size())))
            fail(faces, "texture coordinate index " + fmt(idx[i + k]) +
                            (tex_offset ? " + textureOffset " + std::to_string(tex_offset) : "") +
                            " out of range [1, " + std::to_string(texcoords_.size()) +
                            "] of TexCoordData");
          t = static_cast<int>(tg) - 1;
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

void Loader::read_objects(const XMLElement* scene) {
  const XMLElement* objs = child(scene, "Objects", false);
  for (auto* e = objs ? objs->FirstChildElement() : nullptr; e; e = e->NextSiblingElement()) {
    std::string name = e->Name();
    ObjectDesc o;
    o.element = describe(e);
    const char* id = e->Attribute("id");
    std::string key = id ? id : "";
    if (name == "Mesh" || name == "Triangle") {
      o.material = material_of(e);
      const char* mode = e->Attribute("shadingMode");
      bool smooth = mode && std::string(mode) == "smooth";
      o.textures = textures_of(e);
      o.mesh = add_mesh_from_faces(e, child(e, name == "Mesh" ? "Faces" : "Indices", true), smooth,
                                   !o.textures.empty() && !texcoords_.empty());
      o.transform = transform_of(e);
      o.motion = motion_of(e);
      if (name == "Mesh") mesh_objects_[key] = static_cast<int>(scene_.objects.size());
    } else if (name == "MeshInstance") {
      const char* base_id = e->Attribute("baseMeshId");
      if (!base_id) fail(e, "missing baseMeshId");
      // Older files reuse mesh ids for instances; a Mesh with the id wins.
      auto it = mesh_objects_.find(base_id);
      if (it == mesh_objects_.end()) {
        it = instance_objects_.find(base_id);
        if (it == instance_objects_.end())
          fail(e,
               std::string("baseMeshId '") + base_id + "' names no earlier Mesh or MeshInstance");
      }
      const ObjectDesc& base = scene_.objects[it->second];
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
      instance_objects_[key] = static_cast<int>(scene_.objects.size());
    } else if (name == "Sphere") {
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

// One of the words `names` (the course's spelling), as its index.
static int keyword(const std::string& word, std::initializer_list<const char*> names) {
  int i = 0;
  for (const char* n : names) {
    if (word == n) return i;
    ++i;
  }
  return -1;
}

static std::string trimmed(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

TextureMapDesc Loader::read_texture_map(const XMLElement* e,
                                        const std::map<std::string, std::string>& images,
                                        std::map<std::string, int>& loaded) {
  TextureMapDesc t;
  t.element = path_of(e);
  TextureDesc& d = t.desc;
  const char* type = e->Attribute("type");
  d.type = keyword(type ? type : "", {"image", "perlin", "checkerboard"});
  if (d.type < 0)
    fail(e, "type '" + shorten(type) + "' is not image, perlin or checkerboard");
  const XMLElement* mode = child(e, "DecalMode", true);
  d.decal = keyword(trimmed(text_of(mode)),
                    {"replace_kd", "blend_kd", "replace_ks", "replace_background",
                     "replace_normal", "bump_normal", "replace_all"});
  if (d.decal < 0) fail_value(mode, "is not a DecalMode of the course");
  d.interpolation = RT_INTERP_NEAREST;
  if (const XMLElement* in = child(e, "Interpolation", false)) {
    d.interpolation = keyword(trimmed(text_of(in)), {"nearest", "bilinear"});
    if (d.interpolation < 0) fail_value(in, "is neither nearest nor bilinear");
  }
  d.normalizer = static_cast<float>(child_number(e, "Normalizer", 255));
  if (!(d.normalizer > 0)) fail_value(child(e, "Normalizer", true), "must be positive");
  d.bump_factor = static_cast<float>(child_number(e, "BumpFactor", 1));
  d.noise_scale = static_cast<float>(child_number(e, "NoiseScale", 1));
  if (!(d.noise_scale > 0)) fail_value(child(e, "NoiseScale", true), "must be positive");
  d.noise_conversion = RT_NOISE_LINEAR;
  if (const XMLElement* nc = child(e, "NoiseConversion", false)) {
    d.noise_conversion = keyword(trimmed(text_of(nc)), {"linear", "absval"});
    if (d.noise_conversion < 0) fail_value(nc, "is neither linear nor absval");
  }
  d.checker_scale = static_cast<float>(child_number(e, "Scale", 1));
  d.checker_offset = static_cast<float>(child_number(e, "Offset", 0));
  d.black = to_float3(child_vec3(e, "BlackColor", {0, 0, 0}));
  d.white = to_float3(child_vec3(e, "WhiteColor", {1, 1, 1}));
  if (d.type == RT_TEXTURE_IMAGE) {
    const XMLElement* ie = child(e, "ImageId", true);
    std::string id = trimmed(text_of(ie));
    auto it = images.find(id);
    if (it == images.end()) fail(ie, "no Image with id '" + shorten(id) + "'");
    auto [slot, fresh] = loaded.emplace(id, static_cast<int>(scene_.images.size()));
    if (fresh) {
      std::filesystem::path path(it->second);
      if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
      try {
        scene_.inputs.push_back(path.string());
        scene_.images.push_back(read_ldr(path.string()));
      } catch (const std::exception& err) {
        fail(ie, std::string("image ") + err.what());
      }
    }
    t.image = slot->second;
  } else if (d.decal == RT_DECAL_REPLACE_NORMAL || d.decal == RT_DECAL_REPLACE_BACKGROUND) {
    fail(mode, "'" + trimmed(text_of(mode)) + "' needs an image texture");
  }
  return t;
}

void Loader::read_textures(const XMLElement* scene) {
  const XMLElement* ts = child(scene, "Textures", false);
  if (!ts) return;
  std::map<std::string, std::string> images;  // Image id -> file, read when first used.
  if (const XMLElement* list = child(ts, "Images", false))
    for (auto* im = list->FirstChildElement("Image"); im; im = im->NextSiblingElement("Image")) {
      const char* id = im->Attribute("id");
      if (!id) fail(im, "missing id attribute");
      std::string path = trimmed(text_of(im));
      if (path.empty()) fail(im, "empty file name");
      images[id] = path;
    }
  std::map<std::string, int> loaded;
  for (auto* e = ts->FirstChildElement("TextureMap"); e; e = e->NextSiblingElement("TextureMap")) {
    const char* id = e->Attribute("id");
    if (!id) fail(e, "missing id attribute");
    TextureMapDesc t = read_texture_map(e, images, loaded);
    if (t.desc.decal == RT_DECAL_REPLACE_BACKGROUND) {
      if (scene_.background_texture >= 0)
        fail(e, "a second replace_background texture (only one background is allowed)");
      scene_.background_texture = static_cast<int>(scene_.textures.size());
    }
    texture_ids_[id] = static_cast<int>(scene_.textures.size());
    scene_.textures.push_back(t);
  }
}

void Loader::read_texcoords(const XMLElement* scene) {
  const XMLElement* td = child(scene, "TexCoordData", false);
  if (!td) return;
  auto v = numbers(td, 0, SIZE_MAX);
  if (v.size() % 2 != 0) fail(td, std::to_string(v.size()) + " numbers is not a multiple of 2");
  for (size_t i = 0; i + 1 < v.size(); i += 2) texcoords_.push_back({v[i], v[i + 1]});
}

std::vector<int> Loader::textures_of(const XMLElement* e) const {
  std::vector<int> out;
  const XMLElement* t = child(e, "Textures", false);
  if (!t) return out;
  std::istringstream in(text_of(t));
  std::string id;
  while (in >> id) {
    auto it = texture_ids_.find(id);
    if (it == texture_ids_.end()) fail(t, "no TextureMap with id '" + shorten(id) + "'");
    if (scene_.textures[it->second].desc.decal == RT_DECAL_REPLACE_BACKGROUND) continue;
    out.push_back(it->second);
  }
  if (out.size() > RT_MAX_OBJECT_TEXTURES)
    fail_value(t, "lists more than " + std::to_string(RT_MAX_OBJECT_TEXTURES) + " textures");
  return out;
}

// Image textures on a mesh need texture coordinates for every vertex.
void Loader::check_texture_coordinates() const {
  for (const ObjectDesc& o : scene_.objects) {
    if (o.kind != ObjectDesc::kMesh || !scene_.meshes[o.mesh].uvs.empty()) continue;
    for (int t : o.textures)
      if (scene_.textures[t].desc.type == RT_TEXTURE_IMAGE)
        throw input_error(file_, o.element,
                          "uses an image texture (" + scene_.textures[t].element +
                              ") but has no texture coordinates (TexCoordData or PLY u v)");
  }
}

SceneDesc Loader::load() {
  tinyxml2::XMLDocument doc;
  errno = 0;
  tinyxml2::XMLError err = doc.LoadFile(file_.c_str());
  const int open_errno = errno;
  if (err == tinyxml2::XML_ERROR_FILE_NOT_FOUND ||
      err == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED)
    throw input_error(file_, "file",
                      std::string("cannot open") +
                          (open_errno ? std::string(": ") + std::strerror(open_errno) : ""));
  // A directory opens but cannot be read; tinyxml2 would call either "malformed at line 0".
  std::error_code ec;
  if (err == tinyxml2::XML_ERROR_FILE_READ_ERROR || std::filesystem::is_directory(file_, ec))
    throw input_error(file_, "file",
                      std::filesystem::is_directory(file_, ec) ? "is a directory, not a scene file"
                                                               : "cannot read");
  scene_.inputs.push_back(file_);
  return read_document(doc, err);
}

SceneDesc Loader::load_text(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  return read_document(doc, doc.Parse(xml.data(), xml.size()));
}

SceneDesc Loader::read_document(const tinyxml2::XMLDocument& doc, tinyxml2::XMLError err) {
  if (err == tinyxml2::XML_ERROR_EMPTY_DOCUMENT)
    throw input_error(file_, "XML", "empty document: no <Scene> element");
  if (err != tinyxml2::XML_SUCCESS) {
    // ErrorStr() ends in ": XMLElement name=ImageName" when it knows the element.
    std::string detail = doc.ErrorStr() ? doc.ErrorStr() : "", where;
    size_t at = detail.find("XMLElement name=");
    if (at != std::string::npos) where = " in <" + shorten(detail.substr(at + 16)) + ">";
    throw input_error(file_, "XML",
                      std::string("malformed at line ") + std::to_string(doc.ErrorLineNum()) +
                          where + ": " + doc.ErrorName());
  }
  const XMLElement* scene = doc.FirstChildElement("Scene");
  if (!scene) throw input_error(file_, "XML", "no <Scene> root element");
  scene_.file = file_;
  // Structure first (unsupported features, repeats, unknown elements), then the values.
  for (const std::string& w : check_scene_structure(doc, file_)) warn(w);
  scene_.background = child_vec3(scene, "BackgroundColor", {});
  scene_.shadow_epsilon = child_number(scene, "ShadowRayEpsilon", 1e-3);
  if (scene_.shadow_epsilon < 0)
    fail_value(child(scene, "ShadowRayEpsilon", true), "must not be negative");
  scene_.intersection_epsilon = child_number(scene, "IntersectionTestEpsilon", 1e-6);
  if (scene_.intersection_epsilon < 0)
    fail_value(child(scene, "IntersectionTestEpsilon", true), "must not be negative");
  if (const XMLElement* d = child(scene, "MaxRecursionDepth", false)) {
    double v = number(d);
    if (v < 0 || v != std::floor(v) || v > RT_MAX_DEPTH)
      fail_value(d, "is not a whole number in [0, " + std::to_string(RT_MAX_DEPTH) + "]");
    scene_.max_depth = static_cast<int>(v);
  }
  read_cameras(scene);
  read_lights(scene);
  read_brdfs(scene);
  read_materials(scene);
  read_transformations(scene);
  read_vertices(scene);
  read_textures(scene);
  read_texcoords(scene);
  read_objects(scene);
  check_texture_coordinates();
  if (scene_.degenerate_triangles > 0)
    warn(file_ + ": Objects: skipped " + std::to_string(scene_.degenerate_triangles) +
         " degenerate triangles");
  return std::move(scene_);
}

}  // namespace

SceneDesc load_scene(const std::string& path, const LoadOptions& options) {
  return Loader(path, options).load();
}

SceneDesc load_scene_text(const std::string& xml, const std::string& name,
                          const LoadOptions& options) {
  return Loader(name, options).load_text(xml);
}

}  // namespace rt
