#include "output_check.h"

#include <unistd.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <vector>

#include "io/image_output.h"
#include "io/moments.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

void check_folder(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw std::runtime_error(dir + ": output directory does not exist");
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(dir + ": output path is not a directory");
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(dir + ": output directory is not writable");
}

// The folder's own limits; POSIX minimums where the file system does not say.
long limit(const std::string& dir, int name, long fallback) {
  const long v = pathconf(dir.c_str(), name);
  return v > 0 ? v : fallback;
}

struct Output {
  fs::path path;
  int camera;
  std::string what;  // "image" or "moments file"
};

}  // namespace

void check_outputs(const SceneDesc& scene, int camera, const std::string& output_dir,
                   bool moments) {
  check_folder(output_dir);
  const long name_max = limit(output_dir, _PC_NAME_MAX, 255);
  const long path_max = limit(output_dir, _PC_PATH_MAX, 4096);
  std::vector<Output> outputs;
  for (int c = 0; c < static_cast<int>(scene.cameras.size()); ++c) {
    if (camera >= 0 && c != camera) continue;
    // Every file the camera writes (src/app/render_job.cpp, write_outputs).
    const fs::path image = fs::path(output_dir) / scene.cameras[c].image_name;
    outputs.push_back({image, c, "image"});
    if (scene.cameras[c].tonemap && is_exr_path(image.string()))
      outputs.push_back({tonemap_path_for(image.string()), c, "tone-mapped image"});
    if (moments) outputs.push_back({moments_path_for(image.string()), c, "moments file"});
  }
  std::map<fs::path, const Output*> seen;
  for (const Output& o : outputs) {
    const CameraDesc& cam = scene.cameras[o.camera];
    auto fail = [&](const std::string& why) {
      throw input_error(scene.file, cam.element,
                        "'" + shorten(cam.image_name) + "': the " + o.what + " " + why);
    };
    const std::string name = o.path.filename().string();
    if (static_cast<long>(name.size()) > name_max)
      fail("name is " + std::to_string(name.size()) + " bytes; the file system allows " +
           std::to_string(name_max));
    if (static_cast<long>(fs::absolute(o.path).string().size()) >= path_max)
      fail("path is longer than the file system's limit of " + std::to_string(path_max) + " bytes");
    auto [it, first] = seen.emplace(fs::absolute(o.path).lexically_normal(), &o);
    if (!first) {
      const Output& other = *it->second;
      fail("would replace the " + other.what + " of camera " + std::to_string(other.camera) + " (" +
           scene.cameras[other.camera].element + "): two outputs share '" + shorten(name) + "'");
    }
    std::error_code ec;
    // A relative ImageName ("renders/a.png") writes into a folder below the output folder,
    // which must be there: the renderer creates no folders.
    const fs::path folder = o.path.parent_path();
    if (!fs::is_directory(folder, ec))
      fail("would go into '" + shorten(folder.string(), 200) + "', which " +
           (fs::exists(folder, ec) ? "is not a folder" : "does not exist") +
           " (create it, or choose the output folder with --output-dir)");
    if (!fs::exists(o.path, ec)) continue;
    if (fs::is_directory(o.path, ec)) fail("'" + shorten(o.path.string()) + "' is a directory");
    for (const std::string& input : scene.inputs)
      if (fs::equivalent(o.path, input, ec))
        fail("would overwrite the input file '" + shorten(input, 200) + "'");
  }
}

}  // namespace rt
