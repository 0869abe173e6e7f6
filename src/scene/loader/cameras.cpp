// Cameras and their tone mapping.
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
#include "io/image_output.h"
#include "scene/loader/loader.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

Vec3d Loader::camera_direction(const XMLElement* e, Vec3d v, const char* what) const {
  nonzero(e, v, what);
  const float x = static_cast<float>(v.x), y = static_cast<float>(v.y), z = static_cast<float>(v.z);
  const float squared = x * x + y * y + z * z;
  if (!(squared >= FLT_MIN))
    fail_value(e, "is too short for float: its squared length underflows (scale it up)");
  if (!(squared <= FLT_MAX))
    fail_value(e, "is too long for float: its squared length overflows (scale it down)");
  return v;
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
    if (const char* hand = c->Attribute("handedness")) {
      std::string h = hand;
      if (h != "left" && h != "right")
        fail(c, "handedness '" + shorten(hand) + "' is neither left nor right");
      cam.left_handed = h == "left";
    }
    cam.position = vec3(child(c, "Position", true));
    const XMLElement* up = child(c, "Up", true);
    cam.up = camera_direction(up, vec3(up), "is a zero-length vector");
    cam.near_distance = number(child(c, "NearDistance", true));
    if (!(cam.near_distance > 0)) fail_value(child(c, "NearDistance", true), "must be positive");
    const char* type = c->Attribute("type");
    if (type && std::string(type) == "lookAt") {
      // hw6's lookAt cameras may give a <Gaze> direction instead of a <GazePoint>.
      if (!child(c, "GazePoint", false) && child(c, "Gaze", false)) {
        cam.gaze = camera_direction(child(c, "Gaze", true), vec3(child(c, "Gaze", true)),
                                    "is a zero-length vector");
      } else {
        Vec3d target = vec3(child(c, "GazePoint", true));
        cam.gaze = camera_direction(child(c, "GazePoint", true), target - cam.position,
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
      cam.gaze = camera_direction(child(c, "Gaze", true), vec3(child(c, "Gaze", true)),
                                  "is a zero-length vector");
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
    // Output stays inside --output-dir: a file name or a relative path below it, never
    // out of it. Its folders must exist there (checked with the output folder, before any
    // render: src/app/output_check.cpp).
    const std::filesystem::path image_path(image);
    bool escapes = image_path.is_absolute() || image.find('\\') != std::string::npos;
    for (const auto& part : image_path) escapes = escapes || part == "..";
    if (escapes)
      fail_value(name,
                 "must be a file name or a relative path below the output folder (no '..', "
                 "not absolute); choose the folder with --output-dir");
    const std::string file_name = image_path.filename().string();
    if (file_name.empty() || file_name == ".")
      fail_value(name, "names a folder, not an image file");
    if (image_format_of(image) == ImageFormat::kUnknown)
      fail_value(name,
                 "has an extension the renderer cannot write (.png, .jpg or .jpeg, written as "
                 "JPEG of quality 95, and .exr)");
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
    read_renderer(c, &cam);
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

// <Renderer>PathTracing</Renderer> and its <RendererParams> (hw6/SPEC.txt, section 3.3):
// without them, or with an empty <Renderer>, the camera keeps the course's recursive ray
// tracer. Parameters without PathTracing would silently change nothing, so they are errors.
void Loader::read_renderer(const XMLElement* c, CameraDesc* cam) const {
  const XMLElement* renderer = child(c, "Renderer", false);
  const XMLElement* params = child(c, "RendererParams", false);
  std::string name = renderer ? text_of(renderer) : std::string();
  name.erase(0, name.find_first_not_of(" \t\r\n"));
  name.erase(name.find_last_not_of(" \t\r\n") + 1);
  if (!name.empty() && name != "PathTracing")
    fail_value(renderer, "is not supported (the only renderer is PathTracing)");
  cam->path_tracing = !name.empty();
  if (!params) return;
  std::istringstream words(text_of(params));
  std::string word;
  int flags = 0;
  while (words >> word) {
    if (word == "NextEventEstimation")
      flags |= RT_FLAG_NEXT_EVENT;
    else if (word == "ImportanceSampling")
      flags |= RT_FLAG_IMPORTANCE_SAMPLING;
    else if (word == "RussianRoulette")
      flags |= RT_FLAG_RUSSIAN_ROULETTE;
    else
      fail(params, "'" + shorten(word) +
                       "' is not a path-tracing option (NextEventEstimation, "
                       "ImportanceSampling, RussianRoulette)");
  }
  if (flags != 0 && !cam->path_tracing)
    fail(params, "'" + shorten(text_of(params)) +
                     "' needs <Renderer>PathTracing</Renderer> in the same camera");
  cam->path_flags = flags;
}

}  // namespace loader
}  // namespace rt
