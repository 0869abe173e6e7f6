// The course's checkerboard, as its specification's pseudo-code writes it: an integer
// cast (towards zero) and %, so the squares mirror at 0 rather than continue across it.
#ifndef RT_CHECKERBOARD_H
#define RT_CHECKERBOARD_H

#include "../util/math.h"
#include "texture_types.h"

RT_DEVICE int CheckerParity(real x, real offset, real scale) {
  return ((int)((x + offset) * scale) % 2) != 0;
}

RT_DEVICE real3 CheckerboardTexture(RT_GLOBAL const TextureDesc* t, real3 p) {
  int x = CheckerParity(p.x, t->checker_offset, t->checker_scale);
  int y = CheckerParity(p.y, t->checker_offset, t->checker_scale);
  int z = CheckerParity(p.z, t->checker_offset, t->checker_scale);
  return ToReal3((x != y) != z ? t->black : t->white);
}

#endif  // RT_CHECKERBOARD_H
