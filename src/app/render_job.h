// The images of a job (every selected camera of every scene file given, in order), the
// checks that run before any render, and the one way a finished image is written: shared by
// the single-process driver (main.cpp) and the distributed one (distributed/).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli.h"
#include "integrator/render.h"
#include "scene/scene.h"

namespace rt {

// One scene file, loaded, checked against --camera and scaled by --resolution-scale.
struct JobScene {
  std::string path;
  SceneDesc desc;
  double load_ms = 0;
};

// Throws input_error / runtime_error (one line) on a bad file or a missing --camera.
JobScene load_job_scene(const std::string& path, const CliOptions& opt, bool print_warnings);

// The output directory exists, is a directory and is writable; throws one line otherwise.
void check_output_dir(const CliOptions& opt);

// Where camera `camera` of `scene` is written.
std::string image_path(const CliOptions& opt, const JobScene& scene, int camera);

// Throws input_error (one line) when --camera names a camera the scene file lacks.
void check_camera_choice(const CliOptions& opt, const JobScene& scene);

// One file a camera writes; `what` names it in messages.
struct CameraOutput {
  std::string path;
  const char* what;  // "image", "tone-mapped image", "moments file", "checkpoint"
  // Written only with checkpoints and removed once the image is done (image_checkpoint.h):
  // not one of the outputs whose presence makes the camera complete.
  bool checkpoint = false;
};

// Every file camera `camera` writes to `image`, the one listing of them: the image, the
// tone-mapped PNG beside an .exr of a camera with <Tonemap>, with --moments its moment file,
// and its checkpoint.
std::vector<CameraOutput> camera_outputs(const CliOptions& opt, const CameraDesc& cam,
                                         const std::string& image);

// The cameras of `scene` to render: --camera's or all; with --skip-existing or --resume
// without those whose outputs all exist and are complete (io/partial_mark.h); a partial
// one is named (unless --quiet) with whether its checkpoint continues it.
std::vector<int> job_cameras(const CliOptions& opt, const JobScene& scene);

// The device the options ask for; `gpu_rank` and `threads` as DeviceOptions has them.
DeviceOptions device_options(const CliOptions& opt, int gpu_rank, int threads);

// Host bytes the outputs of one image take besides the device's film.
uint64_t output_bytes(uint64_t pixels, bool moments);

// Writes the image (and with --moments its moment file) of camera `camera` of the scene
// file `scene_path` to `out`, atomically, and warns about non-finite samples.
// A camera with <Tonemap> whose image is HDR also gets its tone-mapped PNG. A non-empty
// `samples_mark` marks every output partial (io/partial_mark.h) and leaves the warning to
// the finished image.
void write_outputs(const CliOptions& opt, const std::string& scene_path, int camera,
                   const CameraDesc& cam, const std::string& device_name, const RenderResult& r,
                   const std::string& out, const std::string& samples_mark = "");

}  // namespace rt
