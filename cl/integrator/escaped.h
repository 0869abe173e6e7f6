// What a ray that leaves the scene brings back, for every integrator: the environment
// light, else the background.
#ifndef RT_INTEGRATOR_ESCAPED_H
#define RT_INTEGRATOR_ESCAPED_H

#include "../light/light.h"
#include "../texture/texturing.h"

// Whether a ray of the tree at `depth` that leaves the scene sees anything: every ray sees
// the environment light (the course's mirror and glass spheres reflect and refract it);
// only camera rays see the background, unless --background-on-secondary-miss.
RT_DEVICE int EscapedRaySees(RT_PRIVATE const SceneData* sd, int depth) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  return (RT_HAS(sd, RT_LIGHT_ENVIRONMENT) && h->environment >= 0) || depth == 0 ||
         (h->flags & RT_FLAG_BACKGROUND_ON_SECONDARY_MISS) != 0;
}

// What such a ray sees: the environment light, else the background.
RT_DEVICE real3 EscapedRadiance(RT_PRIVATE const SceneData* sd, real3 direction, real2 pixel_uv) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  if (RT_HAS(sd, RT_LIGHT_ENVIRONMENT) && h->environment >= 0)
    return EnvironmentRadiance(sd, &sd->lights[h->environment], direction);
  return Background(sd, pixel_uv);
}

#endif  // RT_INTEGRATOR_ESCAPED_H
