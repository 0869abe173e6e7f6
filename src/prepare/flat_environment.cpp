// The environment light flattened for the devices: its map as float RGB texels, and the
// cumulative distributions importance sampling inverts (cl/light/environment.h), built in
// double precision from the same mapping functions the kernel uses.
#include <algorithm>
#include <cmath>
#include <vector>

#include "cl/light/environment_map.h"
#include "prepare_stages.h"

namespace rt {

namespace {

// Appends the normalized running sums of f[0..n-1] to cdf: n + 1 values from 0 to exactly 1.
// A row that is black everywhere gets even steps; it is never drawn (its marginal step is 0).
// Returns the sum.
double append_cdf(const double* f, int n, PageAlignedVector<float>& cdf) {
  double total = 0;
  for (int i = 0; i < n; ++i) total += f[i];
  double running = 0;
  cdf.push_back(0.0f);
  for (int i = 1; i < n; ++i) {
    running += f[i - 1];
    cdf.push_back(static_cast<float>(total > 0 ? running / total : double(i) / n));
  }
  cdf.push_back(1.0f);
  return total;
}

}  // namespace

std::vector<double> environment_importance(const ImageF& map, int mapping) {
  const int w = map.width, h = map.height;
  std::vector<double> f(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float jacobian = 0;
      float2 centre = make_float2((x + 0.5f) / w, (y + 0.5f) / h);
      EnvUVToDirection(mapping, centre, &jacobian);
      if (mapping == RT_ENV_PROBE && !(jacobian > 0)) {
        // A texel of a probe image whose centre lies outside the disc but whose square still
        // reaches into it keeps a small weight, so no direction of the disc has density 0.
        double dx = std::max(0.0, std::fabs(2.0 * centre.x - 1.0) - 1.0 / w);
        double dy = std::max(0.0, std::fabs(2.0 * centre.y - 1.0) - 1.0 / h);
        if (dx * dx + dy * dy < 1.0) jacobian = 4.0f * RT_PI * 1e-3f;
      }
      float r = map.at(x, y, 0), g = map.at(x, y, map.channels >= 3 ? 1 : 0),
            b = map.at(x, y, map.channels >= 3 ? 2 : 0);
      double luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
      f[static_cast<size_t>(y) * w + x] = luminance * jacobian;
    }
  return f;
}

void flatten_environment(const SceneDesc& scene, FlatScene& flat) {
  const ImageF& map = scene.environment_map;
  for (const Light& light : scene.lights) {
    if (light.type != RT_LIGHT_ENVIRONMENT) continue;
    const int w = map.width, h = map.height;
    flat.env_texels.resize(static_cast<size_t>(w) * h);
    for (size_t p = 0; p < flat.env_texels.size(); ++p) {
      const float* t = &map.pixels[p * map.channels];
      flat.env_texels[p] =
          map.channels >= 3 ? float4{t[0], t[1], t[2], 0} : float4{t[0], t[0], t[0], 0};
    }
    std::vector<double> f = environment_importance(map, RT_ENV_MAPPING(&light));
    std::vector<double> rows(h);
    for (int y = 0; y < h; ++y)
      rows[y] = append_cdf(&f[static_cast<size_t>(y) * w], w, flat.env_conditional_cdf);
    double total = append_cdf(rows.data(), h, flat.env_marginal_cdf);
    flat.env_power = static_cast<float>(total / (double(w) * h));
  }
}

void place_environment(const SceneDesc& scene, FlatScene& flat) {
  flat.header.environment = -1;
  for (size_t i = 0; i < flat.lights.size(); ++i) {
    Light& light = flat.lights[i];
    if (light.type != RT_LIGHT_ENVIRONMENT) continue;
    flat.header.environment = static_cast<int>(i);
    RT_ENV_WIDTH(&light) = static_cast<float>(scene.environment_map.width);
    RT_ENV_HEIGHT(&light) = static_cast<float>(scene.environment_map.height);
    RT_ENV_INTEGRAL(&light) = flat.env_power;
  }
}

}  // namespace rt
