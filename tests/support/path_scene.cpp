#include "support/path_scene.h"

#include <filesystem>

namespace rt::test {

bool load_path_scene(int size, SceneDesc* scene, std::string* why) {
  const std::string path =
      std::string(RT_SHARED_SCENES_DIR) + "/hw6/pathTracing/cornellbox_jaroslav_path_diffuse.xml";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    *why = path + " is missing (the course's scenes are not here)";
    return false;
  }
  *scene = load_scene(path);
  for (CameraDesc& c : scene->cameras) c.width = c.height = size;
  return true;
}

FlatScene flatten_path_camera(const SceneDesc& scene, int camera, int spp, uint32_t seed) {
  RenderOptions o;
  o.spp = spp;
  o.seed = seed;
  FlatScene flat = prepare_scene(scene, o);
  prepare_camera(flat, scene, camera, o);
  return flat;
}

}  // namespace rt::test
