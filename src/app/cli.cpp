#include "cli.h"

#include "version.h"

namespace rt {
namespace {

OptionTable<RenderOptions> make_device_table() {
  OptionTable<RenderOptions> t("raytracer", "", "");
  t.section("Sampling", Reach::kDevice)
      .integer("--spp", "N", Range::closed(1, 1 << 20), RT_FIELD(spp),
               "samples per pixel, overriding the scene's NumSamples (any count; non-squares "
               "are not stratified)")
      .default_is("NumSamples")
      .integer("--seed", "N", Range::closed(0, 4294967295.0), RT_FIELD(seed),
               "random stream; equal seeds give equal images, bit for bit")
      .choice("--sampler",
              std::vector<std::pair<std::string, SamplerChoice>>{
                  {"auto", SamplerChoice::kAuto},
                  {"independent", SamplerChoice::kIndependent},
                  {"sobol", SamplerChoice::kSobol}},
              RT_FIELD(sampler),
              "where each sample's random numbers come from: independent: a hash per "
              "dimension, the camera's jittered in strata when the spp is a square; sobol: "
              "every dimension an Owen-scrambled Sobol point (stratified at every power-of-two "
              "spp; less noise for the same samples); auto: sobol for path-traced cameras under "
              "--path-estimator mis, independent elsewhere (the course's images)")
      .choice("--filter",
              std::vector<std::pair<std::string, int>>{{"box", RT_FILTER_BOX},
                                                       {"gaussian", RT_FILTER_GAUSSIAN}},
              RT_FIELD(filter), "reconstruction filter")
      // The weight at the support's corner (0.5 px from the centre on both axes, see
      // RenderSample in cl/integrator/integrator.h) is exp(-0.25 / S^2); below S = 0.054 it
      // is no longer a normal float (FLT_MIN = e^-87.3), so pixels turn black or NaN.
      .real("--filter-sigma", "S", Range{0.054, 100, false, true}, RT_FIELD(filter_sigma),
            "standard deviation of the Gaussian filter, in pixels")
      .choice("--lens",
              std::vector<std::pair<std::string, int>>{{"square", RT_LENS_SQUARE},
                                                       {"disk", RT_LENS_DISK}},
              RT_FIELD(lens),
              "lens shape for depth of field (square: the course's lens of edge ApertureSize)")
      .choice("--dielectric",
              std::vector<std::pair<std::string, bool>>{{"split", false}, {"choose", true}},
              RT_FIELD(fresnel_choice),
              "split (as the course): follow both the reflected and the refracted ray; "
              "choose: follow one, picked with the Fresnel probability")
      .choice("--russian-roulette",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"unbiased", true}},
              RT_FIELD(unbiased_roulette),
              "path tracing with RussianRoulette: course (as its reference images: a path the "
              "roulette ends keeps its last hit's light undivided, which brightens the image); "
              "unbiased: pbrt-v4's (survival from the path's weight)")
      .choice("--path-estimator",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"mis", true}},
              RT_FIELD(mis),
              "path tracing: course (as its reference images: with NextEventEstimation, "
              "emission a bounce finds is dropped, and a path splits at glass); mis: light "
              "samples and bounces both count light, weighed by multiple importance sampling "
              "(power heuristic), without the fireflies of light samples near a light; for "
              "path-traced cameras it implies --russian-roulette unbiased, --dielectric choose "
              "and --ellipsoid-lights exact, and the bounce after the last light sample still "
              "finds emission (docs/path_tracing.md)")
      .choice("--ellipsoid-lights",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"exact", true}},
              RT_FIELD(exact_ellipsoid_lights),
              "course: a LightSphere seen through a non-uniform scale lights a point by its "
              "radiance times the solid angle the untransformed sphere subtends in object "
              "space, as the course's images show; exact: by its true solid angle (spheres "
              "agree either way)");
  t.section("Geometry and shading", Reach::kDevice)
      .flag("--cull-back-faces", RT_FIELD(cull_back_faces),
            "camera and reflected rays ignore triangles facing away (the course's hw1 images "
            "were made this way)")
      .flag("--background-on-secondary-miss", RT_FIELD(background_on_secondary_miss),
            "reflected and refracted rays that escape see BackgroundColor (otherwise black; "
            "camera rays always see it)")
      .choice("--reflection-offset",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"facing", true}},
              RT_FIELD(facing_reflection),
              "where a mirror's or conductor's reflected ray starts when the surface is seen "
              "from behind: course: on the side of the normal as modelled, as the course's "
              "renderer (the ray meets the surface again; hw2 grass_desert needs it); facing: "
              "on the viewer's side")
      .choice("--ray-offset",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"robust", true}},
              RT_FIELD(robust_offset),
              "where shadow, reflected and refracted rays start: course: the scene's "
              "ShadowRayEpsilon along the normal, as the course's renderer (its images' shadow "
              "and reflection edges); robust: that plus 8 float ulps of the surface's "
              "coordinates, safe for scenes whose epsilon is small for their size or position")
      .choice("--camera-rays",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"exact", true}},
              RT_FIELD(exact_camera_rays),
              "course: each camera ray's direction formed in world space and float, rounded "
              "as the course's renderer rounds it (its images' steep gradients need it); "
              "exact: formed relative to the camera, without that rounding")
      .choice("--frame",
              std::vector<std::pair<std::string, bool>>{{"camera", true}, {"world", false}},
              RT_FIELD(camera_frame),
              "the coordinates the devices work in: camera: the world moved so that the "
              "camera sits at the origin, then rounded to float (precise far from the "
              "origin); world: the file's coordinates rounded to float, as the course's "
              "renderer holds them (tools/explain_ensemble.py compares the two)")
      .choice("--shadow-offset",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"geometric", true}},
              RT_FIELD(geometric_offset),
              "which normal a shadow ray's origin moves along by ShadowRayEpsilon: course: the "
              "shading normal (interpolated on smooth meshes), as the course's renderer; "
              "geometric: the triangle's own, which never starts it behind the surface")
      .choice("--hit-point",
              std::vector<std::pair<std::string, bool>>{{"ray", true}, {"surface", false}},
              RT_FIELD(ray_hit_point),
              "where a hit lies: ray: origin + t * direction, as the course's renderer forms "
              "it (its images' pixels decided by rounding; docs/course_pixel_residue.md); "
              "surface: rebuilt from the primitive (barycentrics, the unit sphere), on the "
              "surface whatever the distance travelled")
      .flag("--no-scene-epsilon", RT_FIELD(use_scene_epsilon),
            "ignore ShadowRayEpsilon; rely on the scale-aware ray offset alone", false);
  t.section("Kernel build", Reach::kDevice)
      .choice("--precision",
              std::vector<std::pair<std::string, Precision>>{{"float", Precision::kFloat},
                                                             {"double", Precision::kDouble},
                                                             {"auto", Precision::kAuto}},
              RT_FIELD(precision),
              "arithmetic of the shared math on both devices: double is exact to far smaller "
              "distances and costs time (README: precision); scene arrays stay float; an "
              "OpenCL device without cl_khr_fp64 refuses double; auto: double where the "
              "device has it (always on the CPU reference), else float with a notice")
      .flag("--fast-math", RT_FIELD(fast_math),
            "OpenCL: build with -cl-fast-relaxed-math (faster, less exact; the CPU reference "
            "is always precise)");
  return t;
}

OptionTable<CliOptions> make_raytracer_table() {
  OptionTable<CliOptions> t(
      "raytracer", "raytracer SCENE.xml [SCENE2.xml ...] [options]",
      "Renders every camera of each METU CENG795 scene file given (an animation: its frame\n"
      "files) to a PNG named by its ImageName (8-bit RGB). Under mpirun (a build with MPI)\n"
      "the images, or tiles of them, are spread over the ranks, with the same bytes.\n"
      "Exit status: 0 done, 1 bad input or a failed render, 2 bad usage.");
  t.set_version(RT_VERSION);
  t.section("Device selection")
      .choice("--device",
              std::vector<std::pair<std::string, Device>>{
                  {"auto", Device::kAuto}, {"cl", Device::kOpenCl}, {"cpu", Device::kCpu}},
              RT_FIELD(device),
              "auto: OpenCL when a usable device exists, else the CPU reference, with a "
              "notice; cl: OpenCL or an error; cpu: the C++ reference renderer")
      .text("--cl-device", "SEL", RT_FIELD(cl_device),
            "OpenCL device by index (see --list-devices) or name substring")
      .default_is("the first GPU, else the first device")
      .flag("--list-devices", RT_FIELD(list_devices),
            "list OpenCL platforms and devices, then exit")
      .flag("--no-kernel-cache", RT_FIELD(kernel_cache),
            "always compile the kernel; do not read or write the compiled-kernel cache", false)
      .integer("--threads", "N", Range::closed(1, 4096), RT_FIELD(threads),
               "threads of the CPU reference; the image does not depend on it")
      .default_is("all cores");
  t.section("Output")
      .text("--output-dir", "DIR", RT_FIELD(output_dir), "where PNGs are written")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera),
               "render only camera N (0-based, in file order)")
      .default_is("every camera")
      .choice("--quantize", quantize_choices(), RT_FIELD(quantize),
              "radiance to 8 bits after clamping to [0, 255]: truncate as the course's renderer "
              "(its images are matched exactly), or round half away from zero (unbiased)")
      .flag("--quiet,-q", RT_FIELD(quiet),
            "no progress and no notices (progress is also off when stderr is not a terminal)")
      .flag("--stats", RT_FIELD(stats),
            "print the time split (load, BVH build, kernel compile, upload, render), BVH figures, "
            "samples/s, rays/s and the feature bits")
      .flag("--strict", RT_FIELD(load.strict),
            "treat every warning about the scene as an error (unknown elements, repeated ids "
            "that are allowed, skipped degenerate triangles)")
      .flag("--moments", RT_FIELD(moments),
            "also write <image>.moments.exr: per-pixel sample count, mean and variance of the "
            "unclamped radiance, and the first sample's hit (see compare --help and "
            "src/io/moments.h)")
      .real("--resolution-scale", "F", Range::left_open(0, 16), RT_FIELD(resolution_scale),
            "render every camera at F times its resolution (rounded, at least 1), same view")
      .flag("--skip-existing", RT_FIELD(skip_existing),
            "render only the cameras whose outputs (image, tone-mapped PNG, moments) are not "
            "all there and complete, so a job cut short (interrupt, node failure, a cluster's "
            "time limit) goes on where it stopped: a partial image is continued from its "
            "checkpoint when it has one, else rendered again")
      .real("--checkpoint", "S", Range::positive(), RT_FIELD(checkpoint_s),
            "write the image so far, marked partial, and <image>.rtcheckpoint beside it, the "
            "film that --resume continues, at the end of the first pass S or more seconds "
            "after the last write (passes are then planned to last at most S, but at least one "
            "sample of the image, which can take longer); an interrupt writes both too")
      .default_is("only on an interrupt")
      .flag("--resume", RT_FIELD(resume),
            "continue every camera that has an <image>.rtcheckpoint to its full sample count, "
            "with the bytes of an uninterrupted render (a checkpoint made with other settings "
            "is refused; it is removed once the image is complete), skip those whose outputs "
            "are complete (as --skip-existing), and keep checkpoints on an interrupt")
      .integer("--tile-rows", "N", Range::closed(1, 1 << 20), RT_FIELD(tile_rows),
               "under mpirun: rows of a tile when images are cut among the ranks (rounded up "
               "to a multiple of 32); the images do not depend on it")
      .default_is("automatic");
  t.section("Stopping")
      .real("--time-limit", "S", Range::positive(), RT_FIELD(render.stop.time_limit_s),
            "stop sampling an image when its next pass would end more than S seconds of wall "
            "time after its first sample (each image its own S; loading, BVH build and kernel "
            "compile not counted; every pixel keeps the same sample count; at least one pass)")
      .default_is("none")
      .real("--noise-target", "E", Range::positive(), RT_FIELD(render.stop.noise_target),
            "stop sampling once the image's estimated relative error (root mean of var(pixel "
            "mean) / (mean^2 + f^2), f one output level: 1 on the 0-255 scale, Yavg / (key * "
            "255) on a tone-mapped HDR camera) is below E; E^2 estimates the relative MSE of "
            "bench/sweep")
      .default_is("none");
  t.section("Acceleration structure")
      .integer("--bvh-bins", "N", Range::closed(2, 256), RT_FIELD(render.bvh.bins),
               "SAH bins per axis")
      .integer("--bvh-leaf", "N", Range::closed(1, RT_BVH_MAX_LEAF), RT_FIELD(render.bvh.max_leaf),
               "largest leaf the SAH may keep (at most 16, the wide leaf format's limit)")
      .choice("--bvh-width",
              std::vector<std::pair<std::string, int>>{{"auto", 0}, {"4", 4}, {"8", 8}},
              RT_FIELD(render.bvh.width),
              "children per BVH node and triangles per leaf block; auto: the device's fastest "
              "(8 on an OpenCL CPU device, 4 on the CPU reference, which renders only 4, and "
              "on GPUs); the image is the same at either width");
  t.include(device_option_table(), RT_FIELD(render));
  t.section("Kernel build", Reach::kDevice)
      .choice("--kernel",
              std::vector<std::pair<std::string, bool>>{{"generic", true}, {"specialized", false}},
              RT_FIELD(generic_kernel),
              "compile the all-features kernel, or one specialized to the scene's features");
  t.add_env("RT_CL_OPTIONS",
            "extra OpenCL build options appended to the kernel's (a developer's knob, e.g. "
            "-cl-opt-disable); part of the kernel cache key");
  t.add_env("RT_CL_BUILD_LOG",
            "1: print each OpenCL kernel's build log after it builds (with -cl-nv-verbose in "
            "RT_CL_OPTIONS, NVIDIA's holds ptxas's registers and spills) and the render "
            "kernel's private and local memory and largest work-group");
  t.add_env("RT_CL_GPU_FORMS",
            "1: a CPU OpenCL device compiles the kernel's GPU forms too (a developer's knob, to "
            "check on a machine without a GPU that they render the same pixels)");
  t.add_env("RT_CPU_ISA",
            "baseline: the CPU reference runs its baseline x86-64 build even where the CPU has "
            "AVX2 (by default the AVX2 build is chosen at run time; the image is the same)");
  t.add_env("XDG_CACHE_HOME",
            "the compiled-kernel cache is $XDG_CACHE_HOME/raytracer/kernels (when absolute)");
  t.add_env("HOME", "without XDG_CACHE_HOME, the cache is $HOME/.cache/raytracer/kernels");
  return t;
}

}  // namespace

std::vector<std::pair<std::string, Quantize>> quantize_choices() {
  return {{"truncate", Quantize::kTruncate}, {"round", Quantize::kRound}};
}

const OptionTable<RenderOptions>& device_option_table() {
  static const OptionTable<RenderOptions> table = make_device_table();
  return table;
}

const OptionTable<CliOptions>& raytracer_option_table() {
  static const OptionTable<CliOptions> table = make_raytracer_table();
  return table;
}

CliOptions parse_arguments(int argc, char** argv, std::string* exit_text) {
  CliOptions o;
  std::vector<std::string> scenes = raytracer_option_table().parse(argc, argv, &o, exit_text);
  if (!exit_text->empty()) return o;
  o.scenes = scenes;
  if (o.scenes.empty() && !o.list_devices) throw UsageError("no scene file given");
  return o;
}

CliOptions parse_cli(int argc, char** argv) {
  std::string exit_text;
  CliOptions o;
  try {
    o = parse_arguments(argc, argv, &exit_text);
  } catch (const UsageError& e) {
    raytracer_option_table().usage_error(e.what());
  }
  if (!exit_text.empty()) {
    std::fputs(exit_text.c_str(), stdout);
    std::exit(0);
  }
  return o;
}

}  // namespace rt
