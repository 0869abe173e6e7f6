// The settings the speed-accuracy sweep (bench/sweep.cpp) renders: for the course's
// recursive ray tracer, samples, kernel, fast math, precision, BVH quality and the
// dielectric's split; for a path-traced camera (<Renderer>PathTracing</Renderer>),
// samples, precision and every estimator the scene format offers (next-event estimation,
// cosine importance sampling, Russian roulette: off, the course's or unbiased), and the
// stop rules on both kinds.
#pragma once

#include <string>
#include <vector>

#include "sweep_run.h"

namespace sweep {

std::vector<Config> RayTracingGrid(bool has_cl, bool dielectric);
std::vector<Config> PathTracingGrid(bool has_cl);

// What a configuration's image converges to, as a key: the options that change the
// expectation (next-event estimation, the roulette and its kind; not importance
// sampling, which only changes the noise). Configurations of one class share a reference.
struct ReferenceClass {
  int path_flags = -1;  // -1: not path traced.
  bool unbiased_roulette = false;
  bool operator<(const ReferenceClass& o) const {
    return path_flags != o.path_flags ? path_flags < o.path_flags
                                      : unbiased_roulette < o.unbiased_roulette;
  }
};
ReferenceClass ClassOf(const Config& c, bool path_tracing, int camera_flags);

// The converged reference's configuration of a class: CPU, `spp` samples, seed 1000 (the
// candidates use seed 0), importance sampling on when path traced (same expectation, less
// noise).
Config ReferenceConfig(const ReferenceClass& k, int spp);

// The estimator that converges to the full light transport (no bounce limit, no course
// bias): next-event estimation and the unbiased roulette.
ReferenceClass FullTransport();

// "NEE, importance, RR course" and the like.
std::string EstimatorName(int path_flags, bool unbiased_roulette);

}  // namespace sweep
