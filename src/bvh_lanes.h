// Host-side access to single lanes of the wide node types (LaneFloat, LaneInt of
// cl/scene_types.h), whose layout is a vector type on the C++ side: the BVH collapse and the
// triangle-block builder read and write one child's entry at a time through these.
#pragma once

#include <cstring>

#include "cl/scene_types.h"

namespace rt {

inline int lane_of(const LaneInt& v, int lane) {
  int a[RT_BVH_WIDTH];
  std::memcpy(a, &v, sizeof a);
  return a[lane];
}

inline void set_lane(LaneInt& v, int lane, int value) {
  int a[RT_BVH_WIDTH];
  std::memcpy(a, &v, sizeof a);
  a[lane] = value;
  std::memcpy(&v, a, sizeof a);
}

inline void set_lane(LaneFloat& v, int lane, float value) {
  float a[RT_BVH_WIDTH];
  std::memcpy(a, &v, sizeof a);
  a[lane] = value;
  std::memcpy(&v, a, sizeof a);
}

}  // namespace rt
