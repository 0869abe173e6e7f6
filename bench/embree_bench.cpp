// The gap to the practical limit: the camera rays of a scene traced by this project's wide
// BVH (cl/bvh/bvh.h, the CPU reference's very code) and by Embree 3 (BVH quality HIGH, no
// culling), single rays (rtcIntersect1) and 16-ray packets of 4x4 pixels
// (rtcIntersect16), in one thread, in Mrays per CPU-second of that thread. The rays are
// those the renderer casts (cl/camera/camera.h, GenerateCameraSample), and every tracer's hit
// distances are compared with ours, so what is timed is checked to be the same work.
// With --build, also the BVH build at 1 and 2 threads: ours (prepare_scene, all the
// renderer pays before the first sample) against Embree's HIGH commit, wall and CPU time,
// and whether our tree is the same whatever the thread count.
//
// usage: embree_bench SCENE.xml [--spp N] [--reps N] [--camera N] [--build]
// Embree is a dependency of this benchmark only (Debian's libembree-dev), never of the
// renderer. Scenes with spheres or motion blur are refused: Embree sees world-space
// triangles.
#include <embree3/rtcore.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cl/camera/camera.h"
#include "cl/bvh/intersect.h"
#include "device/cpu/cpu_kernel.h"
#include "util/errors.h"
#include "prepare/flat_scene.h"
#include "scene/scene.h"
#include "util/args.h"
#include "prepare/world_frame.h"

namespace {

struct Args {
  std::string scene;
  int spp = 4;
  int reps = 3;
  int camera = 0;
  bool build = false;
  bool ours_only = false;
};

double ThreadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// CPU time of every thread of the process (builds run on several).
double ProcessCpuSeconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double WallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Camera rays grouped in 4x4-pixel tiles (one sample each), so that a tile is one packet;
// tiles cut by the image's edge have fewer rays.
struct RaySet {
  std::vector<Ray> rays;
  std::vector<size_t> tile_begin;  // Tile i holds rays [tile_begin[i], tile_begin[i + 1]).
};

RaySet CameraRays(const rt::FlatScene& flat) {
  SceneData sd = flat.view();
  const Camera& cam = flat.header.camera;
  RaySet set;
  for (int s = 0; s < cam.samples; ++s)
    for (int ty = 0; ty < cam.height; ty += 4)
      for (int tx = 0; tx < cam.width; tx += 4) {
        set.tile_begin.push_back(set.rays.size());
        for (int y = ty; y < std::min(ty + 4, cam.height); ++y)
          for (int x = tx; x < std::min(tx + 4, cam.width); ++x)
            set.rays.push_back(GenerateCameraSample(&sd, x, y, static_cast<uint>(s)).ray);
      }
  set.tile_begin.push_back(set.rays.size());
  return set;
}

// The scene's meshes as triangles of the frame the rays are in (the camera's, whose origin
// is the world point `eye`: src/prepare/world_frame.h) in one Embree scene of quality HIGH.
RTCScene EmbreeScene(RTCDevice device, const rt::SceneDesc& scene, rt::Vec3d eye) {
  RTCScene es = rtcNewScene(device);
  rtcSetSceneBuildQuality(es, RTC_BUILD_QUALITY_HIGH);
  for (const rt::ObjectDesc& o : scene.objects) {
    if (o.kind != rt::ObjectDesc::kMesh)
      throw std::runtime_error(o.element + ": spheres are not compared with Embree");
    if (o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0)
      throw std::runtime_error(o.element + ": motion blur is not compared with Embree");
    const rt::MeshDesc& mesh = scene.meshes[o.mesh];
    if (mesh.triangles.empty()) continue;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_HIGH);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    const rt::Mat4 to_frame = rt::object_to_frame(o, rt::Vec3d{}, eye);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      rt::Vec3d p = to_frame.point(mesh.positions[i]);
      v[3 * i] = static_cast<float>(p.x);
      v[3 * i + 1] = static_cast<float>(p.y);
      v[3 * i + 2] = static_cast<float>(p.z);
    }
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                mesh.triangles.size()));
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = static_cast<unsigned>(mesh.triangles[i][k]);
    rtcCommitGeometry(g);
    rtcAttachGeometry(es, g);
    rtcReleaseGeometry(g);
  }
  return es;
}

// One tracer: fills t[i] with the hit distance of ray i (infinity for a miss).
using Tracer = std::function<void(const RaySet&, std::vector<float>&)>;

// The renderer's own choice of kernel (AVX2 where the CPU has it; device/cpu_kernel.h).
void TraceOurs(const rt::FlatScene& flat, const RaySet& set, std::vector<float>& t) {
  SceneData sd = flat.view();
  const rt::CpuTraceFunction intersect = rt::select_cpu_kernel(false).intersect_closest;
  for (size_t i = 0; i < set.rays.size(); ++i) {
    Hit hit;
    t[i] = intersect(&sd, &set.rays[i], &hit) ? hit.t : INFINITY;
  }
}

void TraceEmbree1(RTCScene es, const RaySet& set, std::vector<float>& t) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  for (size_t i = 0; i < set.rays.size(); ++i) {
    const Ray& r = set.rays[i];
    RTCRayHit rh;
    rh.ray.org_x = r.origin.x;
    rh.ray.org_y = r.origin.y;
    rh.ray.org_z = r.origin.z;
    rh.ray.dir_x = r.direction.x;
    rh.ray.dir_y = r.direction.y;
    rh.ray.dir_z = r.direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = r.tmax;
    rh.ray.time = 0.0f;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(es, &ctx, &rh);
    t[i] = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : INFINITY;
  }
}

// Packets of one 4x4 tile; the context tells Embree they are coherent (camera rays).
void TraceEmbree16(RTCScene es, const RaySet& set, std::vector<float>& t) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (size_t tile = 0; tile + 1 < set.tile_begin.size(); ++tile) {
    size_t first = set.tile_begin[tile], n = set.tile_begin[tile + 1] - first;
    alignas(64) RTCRayHit16 p;
    alignas(64) int valid[16];
    for (size_t k = 0; k < 16; ++k) {
      const Ray& r = set.rays[first + std::min(k, n - 1)];
      valid[k] = k < n ? -1 : 0;
      p.ray.org_x[k] = r.origin.x;
      p.ray.org_y[k] = r.origin.y;
      p.ray.org_z[k] = r.origin.z;
      p.ray.dir_x[k] = r.direction.x;
      p.ray.dir_y[k] = r.direction.y;
      p.ray.dir_z[k] = r.direction.z;
      p.ray.tnear[k] = 0.0f;
      p.ray.tfar[k] = r.tmax;
      p.ray.time[k] = 0.0f;
      p.ray.mask[k] = ~0u;
      p.ray.id[k] = 0;
      p.ray.flags[k] = 0;
      p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, es, &ctx, &p);
    for (size_t k = 0; k < n; ++k)
      t[first + k] = p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? p.ray.tfar[k] : INFINITY;
  }
}

// Median rate over `reps` runs, in Mrays per CPU-second of this thread.
double MraysPerCpuSecond(const Tracer& trace, const RaySet& set, int reps, std::vector<float>& t) {
  std::vector<double> rates;
  for (int r = 0; r < reps; ++r) {
    double c0 = ThreadCpuSeconds();
    trace(set, t);
    rates.push_back(set.rays.size() / (ThreadCpuSeconds() - c0) * 1e-6);
  }
  return Median(rates);
}

// Share of rays (percent) on which two tracers agree: both miss, or both hit at distances
// within a relative 1e-4 (Embree's world-space vertices of transformed meshes round
// differently from our object-space test, and its triangle test is not ours).
double Agreement(const std::vector<float>& a, const std::vector<float>& b) {
  size_t same = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    bool ha = std::isfinite(a[i]), hb = std::isfinite(b[i]);
    if (ha == hb && (!ha || std::fabs(a[i] - b[i]) <= 1e-4f * std::max(a[i], b[i]))) ++same;
  }
  return 100.0 * same / std::max<size_t>(1, a.size());
}

size_t Hits(const std::vector<float>& t) {
  return std::count_if(t.begin(), t.end(), [](float x) { return std::isfinite(x); });
}

RTCDevice NewDevice(int threads) {
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  RTCDevice d = rtcNewDevice(config.c_str());
  if (!d) throw std::runtime_error("Embree: rtcNewDevice failed");
  return d;
}

int TraceComparison(const Args& a, const rt::SceneDesc& desc, rt::RenderOptions opt) {
  opt.spp = a.spp;
  // World-space rays and triangles, as Embree's scene holds them (the renderer's default
  // frame is relative to the camera, whose rays would all miss Embree's geometry).
  opt.camera_frame = false;
  rt::FlatScene flat = rt::prepare_scene(desc, opt);
  rt::prepare_camera(flat, desc, a.camera, opt);
  RaySet set = CameraRays(flat);
  if (a.ours_only) {  // For comparing two builds of ours: Embree's part is then only noise.
    std::vector<float> t(set.rays.size());
    double r = MraysPerCpuSecond(
        [&](const RaySet& s, std::vector<float>& out) { TraceOurs(flat, s, out); }, set, a.reps, t);
    std::printf("rays %zu triangles %zu ours %.3f hits %zu\n", set.rays.size(),
                flat.stats.triangles, r, Hits(t));
    return 0;
  }
  RTCDevice device = NewDevice(0);
  const rt::Vec3d eye = opt.camera_frame ? desc.cameras[a.camera].position : rt::Vec3d{};
  RTCScene es = EmbreeScene(device, desc, eye);
  rtcCommitScene(es);
  std::vector<float> ours(set.rays.size()), e1(set.rays.size()), e16(set.rays.size());
  double r_ours = MraysPerCpuSecond(
      [&](const RaySet& s, std::vector<float>& t) { TraceOurs(flat, s, t); }, set, a.reps, ours);
  double r_e1 = MraysPerCpuSecond(
      [&](const RaySet& s, std::vector<float>& t) { TraceEmbree1(es, s, t); }, set, a.reps, e1);
  double r_e16 = MraysPerCpuSecond(
      [&](const RaySet& s, std::vector<float>& t) { TraceEmbree16(es, s, t); }, set, a.reps, e16);
  double agree1 = Agreement(ours, e1), agree16 = Agreement(e1, e16);
  rtcReleaseScene(es);
  rtcReleaseDevice(device);
  // One line of name-value pairs (bench/trace_bench.sh reads it), then the verdict.
  std::printf(
      "rays %zu triangles %zu ours %.3f embree1 %.3f embree16 %.3f ratio1 %.3f hits %zu %zu %zu "
      "agree1 %.4f agree16 %.4f\n",
      set.rays.size(), flat.stats.triangles, r_ours, r_e1, r_e16, r_ours / r_e1, Hits(ours),
      Hits(e1), Hits(e16), agree1, agree16);
  // A few rays through shared edges or grazing a silhouette may differ between two
  // correct tests; more would mean the tracers did not do the same work.
  if (agree1 < 99.9 || agree16 < 99.9) {
    std::fprintf(stderr, "embree_bench: the tracers disagree on %.3f%% / %.3f%% of the rays\n",
                 100 - agree1, 100 - agree16);
    return 1;
  }
  return 0;
}

bool SameBytes(const rt::FlatScene& a, const rt::FlatScene& b) {
  return a.nodes.size() == b.nodes.size() && a.triangles.size() == b.triangles.size() &&
         !std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)) &&
         !std::memcmp(a.triangles.data(), b.triangles.data(),
                      a.triangles.size() * sizeof(Triangle));
}

// Build times at 1 and 2 threads, medians of `reps`: "build THREADS ours WALL_S CPU_S
// embree WALL_S CPU_S", then whether our trees were identical.
int BuildComparison(const Args& a, const rt::SceneDesc& desc, rt::RenderOptions opt) {
  rt::FlatScene first;
  bool identical = true;
  for (int threads : {1, 2}) {
    std::vector<double> ow, oc, ew, ec;
    for (int r = 0; r < a.reps; ++r) {
      opt.bvh.threads = threads;
      double w0 = WallSeconds(), c0 = ProcessCpuSeconds();
      rt::FlatScene flat = rt::prepare_scene(desc, opt);
      ow.push_back(WallSeconds() - w0);
      oc.push_back(ProcessCpuSeconds() - c0);
      if (first.nodes.empty())
        first = std::move(flat);
      else
        identical = identical && SameBytes(first, flat);
      RTCDevice device = NewDevice(threads);
      RTCScene es = EmbreeScene(device, desc, rt::Vec3d{});
      w0 = WallSeconds();
      c0 = ProcessCpuSeconds();
      rtcCommitScene(es);
      ew.push_back(WallSeconds() - w0);
      ec.push_back(ProcessCpuSeconds() - c0);
      rtcReleaseScene(es);
      rtcReleaseDevice(device);
    }
    std::printf("build %d ours %.3f %.3f embree %.3f %.3f\n", threads, Median(ow), Median(oc),
                Median(ew), Median(ec));
  }
  std::printf("same_tree %s\n", identical ? "yes" : "no");
  return identical ? 0 : 1;
}

Args Parse(int argc, char** argv) {
  using rt::Range;
  rt::OptionTable<Args> t(
      "embree_bench", "embree_bench SCENE.xml [options]",
      "Traces the camera rays of SCENE with this project's BVH and with Embree 3 (HIGH\n"
      "quality; single rays and 16-ray packets), one thread, and prints Mrays per CPU-second\n"
      "and how far the hit distances agree; with --build, the BVH build times instead.");
  t.section("Benchmark")
      .integer("--spp", "N", Range::closed(1, 4096), RT_FIELD(spp), "camera rays per pixel")
      .integer("--reps", "N", Range::closed(1, 100), RT_FIELD(reps), "repetitions (median)")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .flag("--build", RT_FIELD(build), "compare BVH build times at 1 and 2 threads")
      .flag("--ours-only", RT_FIELD(ours_only), "trace with our BVH alone (no Embree figures)");
  Args a;
  std::vector<std::string> scenes = t.parse_or_exit(argc, argv, &a);
  if (scenes.size() != 1) t.usage_error("needs one SCENE.xml");
  a.scene = scenes[0];
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  Args a = Parse(argc, argv);
  try {
    rt::SceneDesc desc = rt::load_scene(a.scene);
    if (a.camera >= static_cast<int>(desc.cameras.size()))
      throw std::runtime_error(a.scene + ": no camera " + std::to_string(a.camera));
    rt::RenderOptions opt;
    return a.build ? BuildComparison(a, desc, opt) : TraceComparison(a, desc, opt);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embree_bench: %s\n", e.what());
    return 1;
  }
}
