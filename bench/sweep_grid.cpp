#include "sweep_grid.h"

#include <utility>

namespace sweep {

namespace {

class GridBuilder {
 public:
  explicit GridBuilder(bool has_cl) : has_cl_(has_cl) {}
  void add(std::string axis, std::string name, std::string device, rt::RenderOptions o,
           bool generic = false, int path_flags = -1) {
    if (device == "cl" && !has_cl_) return;
    grid_.push_back({axis, name, device, o, generic, path_flags});
  }
  // Samples per pixel on both devices (the float build), then the same in double.
  void spp_and_precision(std::initializer_list<int> spp, std::initializer_list<int> in_double) {
    for (std::string dev : {"cpu", "cl"})
      for (int n : spp) add("spp", "spp " + std::to_string(n), dev, Spp(n));
    for (std::string dev : {"cpu", "cl"})
      for (int n : in_double) {
        rt::RenderOptions o = Spp(n);
        o.precision = rt::Precision::kDouble;
        add("precision", "--precision double, spp " + std::to_string(n), dev, o);
      }
  }
  // The stop rules on the CPU reference: a noise target each, and a time budget.
  void stop_rules(std::initializer_list<double> targets, double seconds, int cap) {
    for (double e : targets) {
      rt::RenderOptions o = Spp(cap);
      o.stop.noise_target = e;
      char name[64];
      std::snprintf(name, sizeof name, "--noise-target %g", e);
      add("stop", name, "cpu", o);
    }
    rt::RenderOptions o = Spp(cap);
    o.stop.time_limit_s = seconds;
    char name[64];
    std::snprintf(name, sizeof name, "--time-limit %g", seconds);
    add("stop", name, "cpu", o);
  }
  static rt::RenderOptions Spp(int n) {
    rt::RenderOptions o;
    o.spp = n;
    return o;
  }
  std::vector<Config> take() { return std::move(grid_); }

 private:
  bool has_cl_;
  std::vector<Config> grid_;
};

constexpr int kRouletteFlags = RT_FLAG_RUSSIAN_ROULETTE;

}  // namespace

std::vector<Config> RayTracingGrid(bool has_cl, bool dielectric) {
  GridBuilder g(has_cl);
  g.spp_and_precision({1, 4, 16, 64}, {4, 16, 64});
  rt::RenderOptions base = GridBuilder::Spp(16);
  g.add("kernel", "generic kernel", "cl", base, true);
  rt::RenderOptions fast = base;
  fast.fast_math = true;
  g.add("math", "-cl-fast-relaxed-math", "cl", fast);
  for (auto [bins, leaf] :
       {std::pair{4, 1}, std::pair{8, 2}, std::pair{32, 8}, std::pair{64, 16}}) {
    rt::RenderOptions o = base;
    o.bvh.bins = bins;
    o.bvh.max_leaf = leaf;
    std::string n = "bvh bins " + std::to_string(bins) + " leaf " + std::to_string(leaf);
    g.add("bvh", n, "cpu", o);
    g.add("bvh", n, "cl", o);
  }
  if (dielectric)
    for (std::string dev : {"cpu", "cl"})
      for (int spp : {16, 64}) {
        rt::RenderOptions o = GridBuilder::Spp(spp);
        o.fresnel_choice = true;
        g.add("dielectric", "choose by Fresnel, spp " + std::to_string(spp), dev, o);
      }
  g.stop_rules({0.1, 0.05}, 1.0, 4096);
  return g.take();
}

std::vector<Config> PathTracingGrid(bool has_cl) {
  GridBuilder g(has_cl);
  g.spp_and_precision({1, 4, 16, 64, 256}, {16, 64});
  g.add("kernel", "generic kernel", "cl", GridBuilder::Spp(16), true);
  // Every estimator of the format, at three sample counts, on the CPU reference (the
  // devices agree bit for bit; the spp rows above show the OpenCL times).
  for (int nee : {0, RT_FLAG_NEXT_EVENT})
    for (int is : {0, RT_FLAG_IMPORTANCE_SAMPLING})
      for (int rr : {0, 1, 2}) {
        const int flags = nee | is | (rr ? kRouletteFlags : 0);
        for (int spp : {4, 16, 64}) {
          rt::RenderOptions o = GridBuilder::Spp(spp);
          o.unbiased_roulette = rr == 2;
          g.add("estimator", EstimatorName(flags, rr == 2), "cpu", o, false, flags);
        }
      }
  g.stop_rules({0.2, 0.1}, 1.0, 4096);
  return g.take();
}

ReferenceClass ClassOf(const Config& c, bool path_tracing, int camera_flags) {
  ReferenceClass k;
  if (!path_tracing) return k;
  const int flags = c.path_flags >= 0 ? c.path_flags : camera_flags;
  k.path_flags = flags & (RT_FLAG_NEXT_EVENT | kRouletteFlags);
  k.unbiased_roulette = (flags & kRouletteFlags) != 0 && c.opt.unbiased_roulette;
  return k;
}

Config ReferenceConfig(const ReferenceClass& k, int spp) {
  Config c{"reference", "reference", "cpu", {}, false, -1};
  c.opt.spp = spp;
  c.opt.seed = 1000;  // Independent of the candidates' seed 0.
  if (k.path_flags >= 0) {
    c.path_flags = k.path_flags | RT_FLAG_IMPORTANCE_SAMPLING;
    c.opt.unbiased_roulette = k.unbiased_roulette;
  }
  return c;
}

ReferenceClass FullTransport() { return {RT_FLAG_NEXT_EVENT | kRouletteFlags, true}; }

std::string EstimatorName(int flags, bool unbiased_roulette) {
  std::string s = (flags & RT_FLAG_NEXT_EVENT) ? "NEE" : "no NEE";
  s += (flags & RT_FLAG_IMPORTANCE_SAMPLING) ? ", importance" : ", uniform";
  if (!(flags & kRouletteFlags))
    s += ", RR off";
  else
    s += unbiased_roulette ? ", RR unbiased" : ", RR course";
  return s;
}

}  // namespace sweep
