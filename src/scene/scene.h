// The scene as read from the course's XML format, before flattening for the devices.
#pragma once

#include <string>
#include <vector>

#include "cl/scene_types.h"
#include "image/image.h"
#include "image/tonemap.h"
#include "util/mat4.h"

// Lights as the file describes them (global, beside the device types they become);
// prepare_camera turns them into the device's tagged Light array (cl/scene_types.h).
// Positions stay in double until the world is moved into the camera's frame
// (src/prepare/world_frame.h); the other members are frame-independent and already float.
struct PointLight {
  rt::Vec3d position;
  float3 intensity;
};

// A parallelogram corner + s * edge1 + t * edge2; the course's square lights are the
// special case of two orthogonal edges of length Size centred on Position.
struct AreaLight {
  rt::Vec3d corner;
  float3 edge1;
  float3 edge2;
  float3 normal;
  float3 radiance;
  float area = 0;
};

namespace rt {

struct CameraDesc {
  std::string image_name;
  std::string element;  // Where the name was read, for messages: "Cameras > Camera id=1 > ImageName".
  Vec3d position, gaze, up;
  double left = -1, right = 1, bottom = -1, top = 1, near_distance = 1;
  int width = 0, height = 0;
  int samples = 1;
  double aperture = 0, focus_distance = 1;
  // handedness="left" (hw5/head_env_light, ported from pbrt, whose LookAt is left-handed):
  // the camera's right vector is up x gaze instead of gaze x up, which mirrors the image.
  bool left_handed = false;
  // <Tonemap>: the film is written as HDR and tone mapped to the 8-bit image beside it.
  bool tonemap = false;
  PhotographicParams tonemap_params;
  // <Renderer>PathTracing</Renderer>: the path tracer of cl/integrator/path.h, with the
  // RT_FLAG_NEXT_EVENT / IMPORTANCE_SAMPLING / RUSSIAN_ROULETTE options of <RendererParams>.
  bool path_tracing = false;
  int path_flags = 0;
};

// A triangle mesh in its own object space; instances share it.
struct MeshDesc {
  std::string element;  // For messages, e.g. "Mesh id=3".
  std::vector<Vec3d> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<double, 2>> uvs;  // Per position; empty without texture coordinates.
  bool smooth = false;
};

struct ObjectDesc {
  enum Kind { kMesh, kSphere };
  Kind kind = kMesh;
  std::string element;
  int mesh = -1;  // Index into SceneDesc::meshes.
  int material = 0;
  Mat4 transform;  // Object to world; for spheres it includes centre and radius.
  Vec3d motion;    // World-space translation over the shutter.
  std::vector<int> textures;  // Indices into SceneDesc::textures.
  // LightMesh and LightSphere (hw6): the object also emits this radiance, and is a light.
  bool emits = false;
  Vec3d radiance;
};

// One TextureMap; `desc` holds its device parameters except the image placement.
struct TextureMapDesc {
  std::string element;
  TextureDesc desc{};
  int image = -1;  // Index into SceneDesc::images (image textures).
};

struct SceneDesc {
  std::string file;
  std::vector<CameraDesc> cameras;
  Vec3d background, ambient;
  double shadow_epsilon = 1e-3;
  double intersection_epsilon = 1e-6;
  int max_depth = 6;
  std::vector<PointLight> point_lights;
  std::vector<AreaLight> area_lights;
  // Lights of the other types, already in device form (type, members as documented in
  // cl/scene_types.h); prepare_camera places them after the point and area lights.
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<MeshDesc> meshes;
  std::vector<ObjectDesc> objects;
  std::vector<ImageF> images;  // Decoded texture images (those a TextureMap uses).
  // The map of the environment light (SphericalDirectionalLight; width 0 without one).
  ImageF environment_map;
  std::vector<TextureMapDesc> textures;
  int background_texture = -1;
  int degenerate_triangles = 0;  // Skipped at load time, reported by --stats.
  std::vector<std::string> warnings;
  std::vector<std::string> inputs;  // Every file read: the scene and its PLY files.
};

struct LoadOptions {
  bool strict = false;  // Every warning is an error (--strict).
  // Reads the XML, its structure and its cameras only, and lists in `inputs` every file the
  // scene names (PLY, binaryFile, images) without reading one: the job's first pass, which
  // plans its outputs before any scene is loaded in full (src/app/output_plan.h).
  bool outline = false;
};

// Reads a scene file; throws rt::InputError with one line naming the file, the element
// and the value when the scene cannot be rendered. Warnings (unknown elements, skipped
// degenerate triangles) are collected in SceneDesc::warnings, or thrown with `strict`.
// Unsupported features and duplicates: see scene_schema.h.
SceneDesc load_scene(const std::string& path, const LoadOptions& options = {});

// The same from XML text in memory; `name` stands for the file in messages and locates
// relative PLY paths.
SceneDesc load_scene_text(const std::string& xml, const std::string& name,
                          const LoadOptions& options = {});

inline float3 to_float3(Vec3d v) {
  return make_float3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

}  // namespace rt
