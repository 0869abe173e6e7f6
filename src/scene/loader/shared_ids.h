// The id namespaces several element kinds share, because one reference may name any of
// them: the one table of them, read by the structure check (scene/scene_schema.cpp), which
// refuses a clash, and by the loader's lookups (a MeshInstance's baseMeshId). Every kind
// not listed has ids of its own: a <Material>'s id never clashes with a <Mesh>'s.
#pragma once

#include <string>
#include <vector>

namespace rt {

struct SharedIds {
  const char* context;             // The schema context that holds them ("BRDFs").
  std::vector<std::string> kinds;  // In the order a reference looks them up.
  const char* reference;           // What refers to them, for the message.
  bool refused;  // Two kinds with one id are an error; otherwise the first kind listed wins.
};

// The group `kind` belongs to inside `context`; nullptr when its ids are its own.
const SharedIds* shared_ids_of(const std::string& context, const std::string& kind);

}  // namespace rt
