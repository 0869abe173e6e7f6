// Exact comparison of the deterministic first-sample outputs of two renders with equal
// seeds: the first camera ray of every pixel is the same ray, so it must hit the same
// primitive of the same instance, at the same distance and with the same normal up to
// float rounding.
#pragma once

#include <cstdint>
#include <vector>

#include "io/moments.h"

namespace cmp {

struct ExactOptions {
  double t_tol = 1e-4;  // relative: |t_A - t_B| <= t_tol * max(t_A, t_B)
  double n_tol = 1e-4;  // largest normal component difference
  double max_fraction = 0;  // fraction of mismatching pixels tolerated (default none)
};

struct ExactReport {
  size_t pixels = 0, hits = 0;
  size_t hit_mismatch = 0;  // one hit, the other missed
  size_t id_mismatch = 0;   // both hit, different instance or primitive
  size_t t_over = 0, n_over = 0;  // same ids, distance or normal beyond the tolerance
  size_t failing = 0;             // pixels with any of the above
  double max_t_rel = 0, max_n = 0;  // over pixels with the same ids
  std::vector<uint8_t> fail;     // per pixel
  std::vector<float> t_rel;      // per pixel relative distance difference (1 on a mismatch)
  bool pass = true;
};

ExactReport exact_test(const rt::MomentImage& a, const rt::MomentImage& b,
                       const ExactOptions& o);

}  // namespace cmp
