// Affine transforms stored as the three rows of a 3x4 matrix.
#ifndef RT_TRANSFORM_H
#define RT_TRANSFORM_H

#include "../util/math.h"

RT_DEVICE real RowDot(float4 row, real3 p) { return row.x * p.x + row.y * p.y + row.z * p.z; }

RT_DEVICE real3 TransformPoint(RT_GLOBAL const float4* m, real3 p) {
  return make_real3(RowDot(m[0], p) + m[0].w, RowDot(m[1], p) + m[1].w, RowDot(m[2], p) + m[2].w);
}

RT_DEVICE real3 TransformVector(RT_GLOBAL const float4* m, real3 v) {
  return make_real3(RowDot(m[0], v), RowDot(m[1], v), RowDot(m[2], v));
}

// Normals transform by the inverse transpose; m is already the inverse (world to
// object), so this multiplies by its transpose.
RT_DEVICE real3 TransformNormalByInverse(RT_GLOBAL const float4* m, real3 n) {
  return make_real3(m[0].x * n.x + m[1].x * n.y + m[2].x * n.z,
                    m[0].y * n.x + m[1].y * n.y + m[2].y * n.z,
                    m[0].z * n.x + m[1].z * n.y + m[2].z * n.z);
}

#endif  // RT_TRANSFORM_H
