#include "support/cl_harness.h"

#include <stdlib.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "device/cl/cl_device.h"
#include "support/device_harness.h"

namespace fs = std::filesystem;

namespace rt::test {

const std::string kCourseScenes = RT_SHARED_SCENES_DIR;

RenderDevice* shared_cl(std::string* why, bool generic) {
  return shared_device(Device::kOpenCl, why, generic, /*kernel_cache=*/false);
}

fs::path make_temp_dir(const std::string& tag) {
  std::string templ = (fs::temp_directory_path() / ("rt_cl_test_" + tag + "_XXXXXX")).string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed");
  return fs::path(buf.data());
}

Loaded load(const std::string& rel, int spp, int size, int bvh_width) {
  Loaded l;
  l.scene = load_scene(kCourseScenes + rel);
  RenderOptions opt;
  opt.spp = spp;
  opt.bvh.width = bvh_width;
  l.flat = prepare_scene(l.scene, opt);
  prepare_camera(l.flat, l.scene, 0, opt);
  l.kernel = kernel_config(opt);
  // Fewer pixels over the same film: the pixel coordinates follow width and height.
  l.flat.header.camera.width = size;
  l.flat.header.camera.height = size;
  return l;
}

RenderResult render_on_cl(const FlatScene& flat, bool generic, DeviceLoadInfo* info,
                          const KernelConfig& kernel) {
  std::string why;
  RenderDevice* device = shared_cl(&why, generic);
  if (!device) throw std::runtime_error("no OpenCL device: " + why);
  return render_on(*device, flat, {}, info, kernel);
}

std::unique_ptr<RenderDevice> open_cl(const std::string& selector, std::string* why) {
  DeviceOptions options;
  options.cl_selector = selector;
  return create_cl_device(options, why);
}

bool identical(const RenderResult& a, const RenderResult& b) {
  return a.accum.size() == b.accum.size() &&
         std::memcmp(a.accum.data(), b.accum.data(), a.accum.size() * sizeof(PixelAccum)) == 0;
}

}  // namespace rt::test
