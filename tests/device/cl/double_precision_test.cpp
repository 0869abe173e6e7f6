// `--precision double` (cl/util/real.h): the OpenCL kernel and the CPU reference agree bit
// for bit in double as they do in float, on scenes that exercise every part of the shared
// math (triangles and spheres, transforms, smooth normals, area lights, glossy
// reflection, dielectrics, depth of field, motion blur, textures); and double keeps first
// hits where float loses them. Tests that need OpenCL are skipped when no device is usable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "device/cl/cl_program.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"

namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

struct Case {
  const char* scene;
  int size;
  int spp;
};

rt::FlatScene load(const Case& c, bool double_precision) {
  rt::SceneDesc scene = rt::load_scene(kScenes + c.scene);
  rt::RenderOptions opt;
  opt.spp = c.spp;
  opt.precision = double_precision ? rt::Precision::kDouble : rt::Precision::kFloat;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, 0, opt);
  flat.header.camera.width = c.size;
  flat.header.camera.height = c.size;
  return flat;
}

bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(const float4& a, const float4& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z) && same(a.w, b.w);
}
// The fourth lane of a float3 is padding, which OpenCL leaves undefined.
bool same(const float3& a, const float3& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

// The number of pixels whose sums, counts or first hit differ in any bit (all of them when
// the sizes differ).
size_t differing_pixels(const rt::RenderResult& a, const rt::RenderResult& b) {
  if (a.accum.size() != b.accum.size() || a.primary.size() != b.primary.size())
    return std::max(a.accum.size(), b.accum.size());
  size_t n = 0;
  for (size_t i = 0; i < a.accum.size(); ++i) {
    const PixelAccum &p = a.accum[i], &q = b.accum[i];
    const PrimaryInfo &f = a.primary[i], &g = b.primary[i];
    if (!same(p.sum, q.sum) || !same(p.sum_sq, q.sum_sq) || p.rays != q.rays ||
        p.nonfinite != q.nonfinite || f.instance != g.instance || f.primitive != g.primitive ||
        (f.instance >= 0 && (!same(f.t, g.t) || !same(f.normal, g.normal))))
      ++n;
  }
  return n;
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene; }

// A device without cl_khr_fp64 refuses double in one line that names it; float is fine.
TEST(PrecisionSupport, DeviceWithoutFp64RefusesDoubleInOneLine) {
  EXPECT_NO_THROW(rt::check_precision_support("Tiny GPU", false, false));
  EXPECT_NO_THROW(rt::check_precision_support("Big GPU", true, true));
  try {
    rt::check_precision_support("Tiny GPU", false, true);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("Tiny GPU"), std::string::npos) << m;
    EXPECT_NE(m.find("--precision double"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

class PrecisionDouble : public ::testing::TestWithParam<Case> {};

// Same seed, same bytes: every pixel's sums, sample counts and first hit.
TEST_P(PrecisionDouble, KernelMatchesTheCpuReferenceBitForBit) {
  const Case& c = GetParam();
  if (!std::ifstream(kScenes + c.scene)) GTEST_SKIP() << c.scene << " is not present";
  std::string why;
  rt::RenderDevice* cl = rt::test::shared_device(rt::Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  rt::FlatScene flat = load(c, true);
  rt::KernelConfig in_double;
  in_double.double_precision = true;
  rt::RenderResult gpu = rt::test::render_on(*cl, flat, {}, nullptr, in_double);
  rt::RenderResult cpu = rt::test::render_cpu(flat, 0, {}, in_double);
  EXPECT_EQ(differing_pixels(gpu, cpu), 0u) << c.scene;
  // Not the float image: the double build really ran.
  rt::RenderResult in_float = rt::test::render_cpu(load(c, false));
  if (!rt::test::test_precision_double()) {
    EXPECT_GT(differing_pixels(in_float, cpu), 0u) << c.scene;
  }
}

INSTANTIATE_TEST_SUITE_P(
    CourseScenes, PrecisionDouble,
    ::testing::Values(Case{"/hw1/simple.xml", 48, 4}, Case{"/hw2/spheres.xml", 48, 4},
                      Case{"/hw1/bunny.xml", 48, 2}, Case{"/hw3/cornellbox_area.xml", 32, 9},
                      Case{"/hw3/cornellbox_brushed_metal.xml", 32, 9},
                      Case{"/hw3/metal_glass_plates.xml", 32, 9},
                      Case{"/hw3/spheres_dof.xml", 32, 9},
                      Case{"/hw3/cornellbox_boxes_dynamic.xml", 32, 9},
                      Case{"/hw4/ellipsoids_texture.xml", 32, 1},
                      Case{"/hw4/cube_perlin_bump.xml", 32, 1},
                      Case{"/hw4/brickwall_with_normalmap.xml", 32, 1},
                      Case{"/hw6/directLighting/cornellbox_jaroslav_glossy_area_sphere.xml", 32, 4},
                      Case{"/hw6/directLighting/cornellbox_jaroslav_diffuse_area.xml", 32, 4}),
    [](const ::testing::TestParamInfo<Case>& info) {
      std::string name = info.param.scene;
      name = name.substr(name.rfind('/') + 1);
      name = name.substr(0, name.find('.'));
      return name;
    });

}  // namespace
