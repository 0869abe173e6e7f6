#include "fuzz/targets.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli.h"
#include "fuzz/scratch.h"
#include "prepare/flat_scene.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "util/errors.h"

namespace rt {
namespace {

// The scratch folder with a quad as m.ply, written once per process, so fuzzed scenes reach
// the PLY path of the loader through plyFile="m.ply".
std::string scene_folder() {
  static const std::string dir = [] {
    static const char kQuad[] =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n"
        "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n4 0 1 2 3\n";
    fuzz_scratch_file("m.ply", reinterpret_cast<const uint8_t*>(kQuad), sizeof kQuad - 1);
    return fuzz_scratch_dir();
  }();
  return dir;
}

}  // namespace

void fuzz_scene(const uint8_t* data, size_t size) {
  SceneDesc scene;
  try {
    scene = load_scene_text(std::string(reinterpret_cast<const char*>(data), size),
                            scene_folder() + "/fuzz.xml");
  } catch (const InputError&) {
    return;  // Refused with a message: the expected outcome for most inputs.
  }
  RenderOptions options;
  FlatScene flat = prepare_scene(scene, options);
  for (int c = 0; c < static_cast<int>(scene.cameras.size()); ++c)
    prepare_camera(flat, scene, c, options);
}

void fuzz_ply(const uint8_t* data, size_t size) {
  try {
    parse_ply(std::string(reinterpret_cast<const char*>(data), size), "fuzz.ply");
  } catch (const InputError&) {
  }
}

void fuzz_cli(const uint8_t* data, size_t size) {
  std::vector<std::string> args{"raytracer"};
  std::string arg;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += static_cast<char>(data[i]);
    }
  }
  if (!arg.empty()) args.push_back(arg);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::string exit_text;
  try {
    CliOptions o = parse_arguments(static_cast<int>(args.size()), argv.data(), &exit_text);
    // A command line that parses names a scene to render (or only lists devices).
    if (exit_text.empty() && o.scenes.empty() && !o.list_devices)
      throw std::logic_error("no scene, yet accepted");
  } catch (const UsageError& e) {
    if (std::string(e.what()).empty()) throw std::logic_error("a usage error without a message");
  }
}

}  // namespace rt
