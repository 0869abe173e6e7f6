#include "planted_bias.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace cmp {

PlantedBias PlantedBias::parse(const std::string& spec) {
  PlantedBias b;
  if (spec == "none") return b;
  size_t colon = spec.find(':');
  std::string kind = spec.substr(0, colon);
  if (colon == std::string::npos) throw std::invalid_argument("bias '" + spec + "' needs :AMOUNT");
  char* end = nullptr;
  b.amount = std::strtod(spec.c_str() + colon + 1, &end);
  if (*end) throw std::invalid_argument("bias '" + spec + "': bad amount");
  if (kind == "light") b.kind = kLight;
  else if (kind == "roughness") b.kind = kRoughness;
  else if (kind == "shift") b.kind = kShift;
  else throw std::invalid_argument("unknown bias '" + kind + "'");
  return b;
}

std::string PlantedBias::label() const {
  char buf[64];
  switch (kind) {
    case kNone: return "none (A vs A)";
    case kLight: std::snprintf(buf, sizeof buf, "light x%.3g", amount); break;
    case kRoughness: std::snprintf(buf, sizeof buf, "roughness x%.3g", amount); break;
    case kShift: std::snprintf(buf, sizeof buf, "camera +%.3g px", amount); break;
  }
  return buf;
}

void apply_bias(const PlantedBias& b, int camera, rt::SceneDesc* scene) {
  float f = static_cast<float>(b.amount);
  switch (b.kind) {
    case PlantedBias::kNone: return;
    case PlantedBias::kLight:
      if (!scene->area_lights.empty()) {
        scene->area_lights[0].radiance = scene->area_lights[0].radiance * f;
      } else if (!scene->point_lights.empty()) {
        scene->point_lights[0].intensity = scene->point_lights[0].intensity * f;
      } else {
        throw std::invalid_argument("the scene has no light to brighten");
      }
      return;
    case PlantedBias::kRoughness: {
      bool any = false;
      for (Material& m : scene->materials)
        if (m.roughness > 0) {
          m.roughness *= f;
          any = true;
        }
      if (!any) throw std::invalid_argument("the scene has no rough material");
      return;
    }
    case PlantedBias::kShift: {
      rt::CameraDesc& c = scene->cameras[camera];
      double px = (c.right - c.left) / c.width;
      c.left += b.amount * px;
      c.right += b.amount * px;
      return;
    }
  }
}

}  // namespace cmp
