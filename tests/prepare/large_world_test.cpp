// Large-world coordinates (src/prepare/world_frame.h): the devices work in float, in the frame of
// the camera, with each mesh's vertices relative to a point of its own. A scene moved far
// from the world's origin must therefore render as it does at the origin, on both devices,
// and the two devices must agree bit for bit at equal seeds.
//
// Each case renders on the CPU reference and, where an OpenCL device exists, on the
// kernel (without one the CL half is skipped with the reason). The figures are printed
// ("[ large world ]") for the README's known limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact.h"
#include "family.h"
#include "io/moments.h"
#include "io/png_io.h"
#include "support/device_harness.h"
#include "support/stability_scenes.h"
#include "welch.h"

namespace {

using namespace stab;
using Dev = rt::Device;

// The devices to run on: the CPU reference always, the kernel where one exists.
std::vector<Dev> Devices() {
  std::vector<Dev> out = {Dev::kCpu};
  std::string why;
  if (rt::test::shared_device(Dev::kOpenCl, &why))
    out.push_back(Dev::kOpenCl);
  else
    std::printf("[ large world ] no OpenCL device, CPU half only: %s\n", why.c_str());
  return out;
}

rt::RenderResult Render(Dev d, const rt::SceneDesc& s, const rt::RenderOptions& o, int camera = 0) {
  rt::FlatScene f = rt::prepare_scene(s, o);
  rt::prepare_camera(f, s, camera, o);
  std::string why;
  rt::RenderDevice* device = rt::test::shared_device(d, &why);
  return rt::test::render_on(*device, f);
}

rt::MomentImage Moments(const rt::RenderResult& r) {
  rt::MomentInfo info;
  info.device = "test";
  return rt::moments_from_render(r, info);
}

// The share of pixels whose 8-bit values (the default truncating conversion) differ by at
// most `levels` in every channel.
double ShareWithin(const rt::RenderResult& a, const rt::RenderResult& b, int levels) {
  rt::Image8 ia = rt::to_8bit(a.width, a.height, a.rgb());
  rt::Image8 ib = rt::to_8bit(b.width, b.height, b.rgb());
  size_t ok = 0, pixels = static_cast<size_t>(a.width) * a.height;
  for (size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(ia.rgb[i * 3 + c] - ib.rgb[i * 3 + c]));
    ok += worst <= levels;
  }
  return static_cast<double>(ok) / pixels;
}

// The two devices at equal seeds: every pixel's sums equal, bit for bit.
void ExpectBitIdentical(const rt::RenderResult& cpu, const rt::RenderResult& cl,
                        const std::string& label) {
  ASSERT_EQ(cpu.accum.size(), cl.accum.size());
  size_t same = 0;
  for (size_t i = 0; i < cpu.accum.size(); ++i)
    same += std::memcmp(&cpu.accum[i].sum, &cl.accum[i].sum, sizeof(float4)) == 0;
  std::printf("[ large world ] %-34s cl vs cpu: %zu of %zu pixels bit-identical\n", label.c_str(),
              same, cpu.accum.size());
  EXPECT_EQ(same, cpu.accum.size()) << label;
}

Vec3d Diagonal(double d) { return V(d, d, d); }

// The case a float world fails first: a small sphere (radius 0.3) on a floor, lit by a
// point light and seen from about 3 units away. Moved by (d, d, d), a float world resolves
// ulp(1e5) = 0.008 (3 % of the radius) and ulp(1e6) = 0.06.
rt::SceneDesc SmallSphere() {
  Builder b;
  rt::SceneDesc& s = b.scene();
  s.background = V(10, 10, 20);
  s.ambient = Gray(8);
  int red = b.material(Plain(V(0.8, 0.25, 0.2), Gray(0.5), 60, Gray(1)));
  int floor = b.material(Plain(Gray(0.6), {}, 1, Gray(1)));
  b.sphere(V(0, 0.3, 0), 0.3, red);
  b.quad(V(-2, 0, -2), V(-2, 0, 2), V(2, 0, 2), V(2, 0, -2), floor);
  b.point_light(V(1.5, 2.5, 2), Gray(600));
  b.camera(V(0.4, 1.1, 2.8), V(0, 0.3, 0), V(0, 1, 0), 0.14, 0.14, 1, 64, 64);
  return s;
}

TEST(LargeWorld, SmallSphereFarFromTheOriginRendersAsAtTheOrigin) {
  const rt::SceneDesc base = SmallSphere();
  rt::RenderOptions o;
  o.spp = 6;  // Not a square: unstratified, independent samples for the Welch test.
  for (Dev d : Devices()) {
    rt::RenderResult a = Render(d, base, o);
    for (double dist : {1e5, 1e6}) {
      const rt::SceneDesc far = MapScene(base, 1, Diagonal(dist));
      rt::RenderResult same_seed = Render(d, far, o);
      rt::RenderOptions other = o;
      other.seed = 1;
      rt::RenderResult b = Render(d, far, other);
      cmp::check_testable(Moments(a), Moments(b), false);
      cmp::Family f = cmp::welch_test(Moments(a), Moments(b), cmp::WelchOptions{});
      cmp::FamilyOptions fo;
      fo.alpha = 1e-3;
      cmp::Verdict v = cmp::decide(f, fo);
      const double within = ShareWithin(a, same_seed, 1);
      const double identical = ShareWithin(a, same_seed, 0);
      std::printf(
          "[ large world ] small sphere at (%g, %g, %g) %-3s welch %s (%zu rejections of %zu), "
          "%.3f %% of pixels within one level of the origin's, %.3f %% identical\n",
          dist, dist, dist, rt::test::device_label(d), v.pass ? "PASS" : "FAIL", v.rejections,
          v.tests, 100 * within, 100 * identical);
      EXPECT_TRUE(v.pass) << dist << " " << rt::test::device_label(d);
      EXPECT_GE(within, 0.999) << dist << " " << rt::test::device_label(d);
    }
  }
}

// The first camera ray of every pixel, with the scene and camera moved 1e5 and 1e6 from
// the origin, finds what it finds at the origin: the same primitive, at the same distance
// and with the same normal up to float rounding of numbers of the stage's size (not of
// the offset's). Spheres, meshes, a box and a moving sphere; several lights.
rt::SceneDesc Stage() {
  Builder b;
  rt::SceneDesc& s = b.scene();
  s.ambient = Gray(6);
  int floor = b.material(Plain(Gray(0.7), Gray(0.1), 10, Gray(1)));
  int red = b.material(Plain(V(0.8, 0.2, 0.2), Gray(0.4), 40, Gray(1)));
  int mirror = b.material(Mirror(Gray(0.85)));
  b.quad(V(-6, 0, -4), V(-6, 0, 6), V(6, 0, 6), V(6, 0, -4), floor);
  b.quad(V(-6, 0, -4), V(6, 0, -4), V(6, 6, -4), V(-6, 6, -4), red);
  b.sphere(V(-1.6, 1, -0.8), 1, red);
  b.sphere(V(1.9, 0.8, -1.8), 0.8, mirror);
  b.sphere(V(-0.4, 0.3, 3.2), 0.3, red, V(0.8, 0, 0));
  b.box(V(-3.6, 0, 0.6), V(-2.9, 0.9, 1.3), floor);
  b.point_light(V(2.5, 5.5, 4), V(14000, 13000, 12000));
  b.area_light(V(-2.6, 4.6, -0.4), V(1.2, 0, 0), V(0, 0, 1.2), V(700, 700, 650));
  b.camera(V(0, 3.2, 8.5), V(0, 0.7, 0), V(0, 1, 0), 0.55, 0.55, 1, 40, 40);
  return s;
}

TEST(LargeWorld, CameraFarFromTheOriginFindsTheSameFirstHits) {
  const rt::SceneDesc base = Stage();
  rt::RenderOptions o;
  o.spp = 1;
  for (Dev d : Devices()) {
    rt::MomentImage ma = Moments(Render(d, base, o));
    for (double dist : {1e5, 1e6}) {
      rt::MomentImage mb = Moments(Render(d, MapScene(base, 1, Diagonal(dist)), o));
      // Float rounding of the stage's own numbers (about 10 units): a few ulps of 10.
      cmp::ExactOptions eo;
      eo.t_tol = 1e-5;
      eo.n_tol = 1e-4;
      cmp::ExactReport rep = cmp::exact_test(ma, mb, eo);
      std::printf(
          "[ large world ] camera at (%g, %g, %g) %-3s %zu of %zu first hits differ (%zu hit/miss, "
          "%zu other primitive, %zu distance, %zu normal), max relative t difference %.2e\n",
          dist, dist, dist, rt::test::device_label(d), rep.failing, rep.pixels, rep.hit_mismatch,
          rep.id_mismatch, rep.t_over, rep.n_over, rep.max_t_rel);
      EXPECT_EQ(rep.failing, 0u) << dist << " " << rt::test::device_label(d);
    }
  }
}

// Each device's renders of the far scenes agree with the other's bit for bit.
TEST(LargeWorld, DevicesAgreeFarFromTheOrigin) {
  std::vector<Dev> devices = Devices();
  if (devices.size() < 2) GTEST_SKIP() << "no OpenCL device to compare with the CPU reference";
  rt::RenderOptions o;
  o.spp = 4;
  for (double dist : {0.0, 1e5, 1e6}) {
    for (const rt::SceneDesc& base : {SmallSphere(), Stage()}) {
      const rt::SceneDesc s = MapScene(base, 1, Diagonal(dist));
      char label[64];
      std::snprintf(label, sizeof label, "%s at %g",
                    base.cameras[0].width == 64 ? "sphere" : "stage", dist);
      ExpectBitIdentical(Render(Dev::kCpu, s, o), Render(Dev::kOpenCl, s, o), label);
    }
  }
}

// Known limit kept as a test: an area light 1e-7 above an opaque table, or in its plane,
// leaks onto the floor under it, because float cannot tell on which side of the table the
// shadow segment ends. The precision that decides is that of the camera's frame, so the
// leak is the same wherever the scene stands; it is measured against the floor lit with
// the table taken away, by a camera under the table 0.36 from the table's centre.
TEST(LargeWorld, AreaLightTouchingASurfaceLeaksTheSameEverywhere) {
  auto scene_at = [](double lift, bool table, double dist) {
    Builder b;
    int wood = b.material(Plain(V(0.7, 0.6, 0.5), Gray(0.3), 20));
    int floor = b.material(Plain(Gray(0.8)));
    if (table) b.quad(V(-2, 0, -2), V(-2, 0, 2), V(2, 0, 2), V(2, 0, -2), wood);
    b.quad(V(-8, -1, -8), V(-8, -1, 8), V(8, -1, 8), V(8, -1, -8), floor);
    b.area_light(V(-0.5, lift, -0.5), V(0, 0, 1), V(1, 0, 0), Gray(500));
    b.camera(V(0, -0.2, 0.3), V(0, -1, 0.3), V(0, 0, -1), 0.5, 0.5, 0.6, 32, 32);
    return MapScene(b.scene(), 1, Diagonal(dist));
  };
  rt::RenderOptions o;
  o.spp = 16;
  o.use_scene_epsilon = false;
  auto sum = [](const rt::RenderResult& r) {
    double total = 0;
    for (float v : r.rgb()) total += v;
    return total;
  };
  for (Dev d : Devices()) {
    for (double lift : {1e-3, 1e-7, 0.0}) {
      double at_origin = 0;
      for (double dist : {0.0, 1e5, 1e6}) {
        const double open = sum(Render(d, scene_at(lift, false, dist), o));
        const double leak = sum(Render(d, scene_at(lift, true, dist), o)) / open;
        std::printf(
            "[ large world ] area light %g above the table, scene at %g, %-3s: %.3f %% of the "
            "light leaks under it\n",
            lift, dist, rt::test::device_label(d), 100 * leak);
        if (dist == 0) at_origin = leak;
        EXPECT_NEAR(leak, at_origin, 0.005) << lift << " at " << dist;
        if (lift >= 1e-4) {
          EXPECT_EQ(leak, 0.0) << lift;
        }
        // Measured when written: 1e-7 leaks 20.1 %, coplanar 99.2 %.
        if (lift > 0 && lift < 1e-4) {
          EXPECT_LT(leak, 0.3) << lift;
        }
      }
    }
  }
}

// Every position fits float on its own (the loader's limit), but an object 3e38 on one
// side of the camera and the camera 3e38 on the other do not fit as a difference: the
// camera's frame is refused with the object's name rather than rendered with infinities.
TEST(LargeWorld, ObjectBeyondFloatRangeFromTheCameraIsRefused) {
  Builder b;
  int m = b.material(Plain(Gray(0.5)));
  b.sphere(V(3e38, 0, 0), 1, m);
  b.point_light(V(0, 0, 0), Gray(1));
  b.camera(V(-3e38, 0, 0), V(0, 0, 0), V(0, 1, 0), 1, 1, 1, 4, 4);
  const rt::SceneDesc s = b.scene();
  rt::RenderOptions o;
  rt::FlatScene f = rt::prepare_scene(s, o);  // In the world's frame both fit.
  try {
    rt::prepare_camera(f, s, 0, o);
    ADD_FAILURE() << "the camera's frame was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Sphere 0: lies beyond float range from the camera"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
