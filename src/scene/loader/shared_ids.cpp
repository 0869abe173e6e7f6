#include "scene/loader/shared_ids.h"

namespace rt {
namespace {

const std::vector<SharedIds>& shared_ids() {
  static const std::vector<SharedIds> kShared = {
      {"BRDFs",
       {"OriginalBlinnPhong", "OriginalPhong", "ModifiedBlinnPhong", "ModifiedPhong",
        "TorranceSparrow"},
       "a Material's BRDF=\"id\"",
       true},
      // The course's veach_ajar and dragon_dynamic scenes reuse Mesh ids for MeshInstances,
      // its Cornell boxes a Mesh id for a LightMesh: a baseMeshId takes the kind listed first.
      {"Objects", {"Mesh", "MeshInstance", "LightMesh"}, "a MeshInstance's baseMeshId", false},
  };
  return kShared;
}

}  // namespace

const SharedIds* shared_ids_of(const std::string& context, const std::string& kind) {
  for (const SharedIds& g : shared_ids())
    if (context == g.context)
      for (const std::string& k : g.kinds)
        if (k == kind) return &g;
  return nullptr;
}

}  // namespace rt
