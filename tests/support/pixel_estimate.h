// One-pixel renders on the CPU reference as statistical estimates, for the closed-form
// tests of the path tracer: the pixel's mean with its standard error, and the check that
// accepts |mean - expected| <= 4.5 standard errors (a false alarm has probability below
// 1e-5 per check, normal approximation over >= 20000 samples) plus 2e-4 relative for the
// float sums of the film (their rounding over 40000 samples stays below it).
#pragma once

#include <string>

#include "prepare/flat_scene.h"
#include "scene/scene.h"

namespace rt::test {

struct PixelStats {
  double mean, standard_error;
};

// Channel 0 of the only pixel of camera 0 of `scene`.
PixelStats RenderOnePixel(const SceneDesc& scene, const RenderOptions& opt = {});

void ExpectMean(const PixelStats& s, double expected, const std::string& what);

// Two estimates of one value agree within 4.5 standard errors of their difference.
void ExpectSameMean(const PixelStats& a, const PixelStats& b, const std::string& what);

// A normalized Lambertian (the hw6 ModifiedPhong, normalized, without its lobe): f = a / pi.
Material Lambert(double a);

}  // namespace rt::test
