// The path tracer's --path-estimator mis (cl/integrator/mis.h) against closed forms, on the
// CPU reference: light samples and bounces that both find a light are weighed so that
// their weights sum to 1, so a weight that does not (a light sample left unweighed, a
// bounce's emission dropped or counted whole, a wrong density) misses each figure by a
// share of its direct light, far outside the tolerance: |mean - expected| <= 4.5 standard
// errors plus 2e-4 relative (tests/support/pixel_estimate.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "path_mis_scenes.h"

namespace {

using namespace rt::test::mis;
using rt::test::ExpectMean;
using rt::test::ExpectSameMean;
using rt::test::Lambert;
using rt::test::RenderOnePixel;

std::string Name(int flags, bool mis) {
  return std::string(mis ? "mis" : "course") + (flags & kNee ? ", NEE" : ", bounces") +
         (flags & kImportance ? ", cosine" : ", uniform") + (flags & kRoulette ? ", RR" : "");
}

// The white furnace of an emitting box: a closed cube whose inner faces are one LightMesh
// of radiance Le and albedo a (normalized Lambertian). Every point sees Le emitted plus a
// times the uniform radiance it receives, so a path of k scatterings adds Le a^k. With next-
// event estimation mis (as the course) reaches MaxRecursionDepth + 1 scatterings, the last by
// the light sample and by the bounce after it; bounces alone reach MaxRecursionDepth; the
// unbiased roulette sums the whole series, Le / (1 - a). Every point lies on the light, the
// light samples of a point near an edge see the adjacent face at distances near 0.
rt::SceneDesc EmittingBox(double albedo, double le, int depth, int samples, int flags) {
  rt::SceneDesc s = Looking({0.1, 0.2, 0.3}, depth, samples, flags);
  s.materials.push_back(Lambert(albedo));
  const double w = 1;
  rt::MeshDesc box;
  const rt::MeshDesc quads[6] = {
      Square(w, -w, 1),
      Square(w, w, -1),
      Face({-w, -w, -w}, {-w, w, -w}, {-w, w, w}, {-w, -w, w}, {1, 0, 0}),
      Face({w, -w, -w}, {w, w, -w}, {w, w, w}, {w, -w, w}, {-1, 0, 0}),
      Face({-w, -w, -w}, {w, -w, -w}, {w, -w, w}, {-w, -w, w}, {0, 1, 0}),
      Face({-w, w, -w}, {w, w, -w}, {w, w, w}, {-w, w, w}, {0, -1, 0})};
  for (const rt::MeshDesc& q : quads) {
    const int base = static_cast<int>(box.positions.size());
    box.positions.insert(box.positions.end(), q.positions.begin(), q.positions.end());
    for (auto t : q.triangles) box.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  AddMesh(&s, box, 0, le);
  return s;
}

double Series(double a, int terms) { return (1 - std::pow(a, terms)) / (1 - a); }

TEST(PathMis, EmittingBoxIsTheSeries) {
  const double a = 0.5, le = 2;
  for (int depth : {0, 2})
    for (int flags : {kNee, kNee | kImportance, kImportance}) {
      const int terms = depth + 1 + ((flags & kNee) ? 1 : 0);
      const std::string what = Name(flags, true) + ", depth " + std::to_string(depth);
      ExpectMean(RenderOnePixel(EmittingBox(a, le, depth, 20000, flags), Mis()),
                 le * Series(a, terms), what);
    }
  for (int flags : {kNee, kNee | kImportance})
    ExpectMean(RenderOnePixel(EmittingBox(a, le, 1, 20000, flags | kRoulette), Mis()), le / (1 - a),
               Name(flags | kRoulette, true));
  // The course's estimator has the same expectation with next-event estimation.
  ExpectMean(RenderOnePixel(EmittingBox(a, le, 2, 20000, kNee | kImportance), Mis(false)),
             le * Series(a, 4), Name(kNee | kImportance, false));
}

// A floor of albedo a under a square LightMesh of half-side s at height h facing down, seen
// at the point below its centre: the irradiance there is the square's form factor,
// E = 4 L X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2)), X = s / h, and the floor sends a E / pi.
// At depth 0 only direct light counts: mis's light sample and the bounce after it, or the
// course's light sample alone, or with bounces alone (depth 1) the bounce.
TEST(PathMis, FloorUnderASquareLight) {
  const double a = 0.5, le = 3, half = 1, h = 1;
  const double x = half / h, r = std::sqrt(1 + x * x);
  const double expected = a / M_PI * 4 * le * x / r * std::atan(x / r);
  for (int flags : {kNee, kNee | kImportance, kImportance})
    for (bool mis : {true, false}) {
      rt::SceneDesc s = Looking({0, 0, 0.5}, (flags & kNee) ? 0 : 1, 20000, flags);
      s.materials.push_back(Lambert(a));
      AddMesh(&s, Square(50, 0, 1), 0);
      AddMesh(&s, Square(half, h, -1), 0, le);
      ExpectMean(RenderOnePixel(s, Mis(mis)), expected, Name(flags, mis));
    }
}

// A floor of albedo a below a LightSphere of radius r whose centre is at height d: the
// point below the centre receives E = pi L r^2 / d^2 and sends a L r^2 / d^2.
TEST(PathMis, FloorUnderASphereLight) {
  const double a = 0.5, le = 4, radius = 0.5, d = 1.5;
  const double expected = a * le * radius * radius / (d * d);
  for (int flags : {kNee, kNee | kImportance}) {
    rt::SceneDesc s = Looking({0, 0, 0.5}, 0, 20000, flags);
    s.materials.push_back(Lambert(a));
    AddMesh(&s, Square(50, 0, 1), 0);
    AddSphere(&s, {0, 0, d}, radius, 0, le);
    ExpectMean(RenderOnePixel(s, Mis()), expected, Name(flags, true));
  }
}

// A floor of albedo a under a constant sky L reflects a L, whichever of the environment's
// samplers draws the light samples, with or without weighing them against the bounces.
TEST(PathMis, FloorUnderAConstantSky) {
  const double a = 0.25, sky = 2;
  for (int sampler : {RT_ENV_SAMPLE_IMPORTANCE, RT_ENV_SAMPLE_UNIFORM, RT_ENV_SAMPLE_COSINE})
    for (int flags : {kNee, kNee | kImportance})
      for (bool mis : {true, false}) {
        rt::SceneDesc s = Looking({0, 0, 0.5}, 0, 20000, flags);
        s.materials.push_back(Lambert(a));
        AddMesh(&s, Square(50, 0, 1), 0);
        AddSky(&s, sky, sampler);
        ExpectMean(RenderOnePixel(s, Mis(mis)), a * sky,
                   Name(flags, mis) + ", sampler " + std::to_string(sampler));
      }
}

// Under a sky that is brighter overhead (no closed form), with a square light beside it, at
// depth 2: mis and the course's estimator converge to the same value.
TEST(PathMis, AgreesWithTheCourseUnderAVaryingSky) {
  for (int sampler : {RT_ENV_SAMPLE_IMPORTANCE, RT_ENV_SAMPLE_COSINE})
    for (int flags : {kNee, kNee | kImportance}) {
      rt::SceneDesc s = Looking({0.1, 0, 0.5}, 2, 20000, flags);
      s.materials.push_back(Lambert(0.6));
      AddMesh(&s, Square(50, 0, 1), 0);
      AddMesh(&s, Face({0.5, -0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 1}, {0.5, -0.5, 1}, {-1, 0, 0}),
              0);
      AddMesh(&s, Square(0.3, 1.2, -1), 0, 5);
      AddSky(&s, 0.5, sampler, 4);
      ExpectSameMean(RenderOnePixel(s, Mis()), RenderOnePixel(s, Mis(false)),
                     Name(flags, true) + ", sampler " + std::to_string(sampler));
    }
}

}  // namespace
