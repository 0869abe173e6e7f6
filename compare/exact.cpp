#include "exact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cmp {

ExactReport exact_test(const rt::MomentImage& a, const rt::MomentImage& b,
                       const ExactOptions& o) {
  if (a.width != b.width || a.height != b.height) throw std::runtime_error("sizes differ");
  ExactReport r;
  r.pixels = a.pixels();
  r.fail.assign(r.pixels, 0);
  r.t_rel.assign(r.pixels, 0.0f);
  for (size_t i = 0; i < r.pixels; ++i) {
    bool ha = a.instance[i] >= 0, hb = b.instance[i] >= 0;
    bool bad = false;
    if (ha != hb) {
      ++r.hit_mismatch;
      bad = true;
    } else if (ha) {
      ++r.hits;
      if (a.instance[i] != b.instance[i] || a.primitive[i] != b.primitive[i]) {
        ++r.id_mismatch;
        bad = true;
      } else {
        double ta = a.first_t[i], tb = b.first_t[i];
        double rel = std::fabs(ta - tb) / std::max({std::fabs(ta), std::fabs(tb), 1e-30});
        r.t_rel[i] = static_cast<float>(rel);
        r.max_t_rel = std::max(r.max_t_rel, rel);
        if (!(rel <= o.t_tol)) {
          ++r.t_over;
          bad = true;
        }
        double dn = 0;
        for (int c = 0; c < 3; ++c)
          dn = std::max(dn, std::fabs(static_cast<double>(a.normal[i * 3 + c]) -
                                      b.normal[i * 3 + c]));
        r.max_n = std::max(r.max_n, dn);
        if (!(dn <= o.n_tol)) {
          ++r.n_over;
          bad = true;
        }
      }
    }
    if (bad) {
      r.fail[i] = 1;
      r.t_rel[i] = 1.0f;
      ++r.failing;
    }
  }
  r.pass = r.failing <= o.max_fraction * static_cast<double>(r.pixels);
  return r;
}

}  // namespace cmp
