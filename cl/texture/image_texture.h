// Image lookups: texels packed as 8-bit RGB in one uint each (red in the low byte),
// values returned on the 0..255 scale; or, for HDR images, three uints per texel holding
// the bits of float R, G, B, returned as they are. Coordinates outside the image repeat the edge
// texel, as the course's specification suggests.
#ifndef RT_IMAGE_TEXTURE_H
#define RT_IMAGE_TEXTURE_H

#include "../util/math.h"
#include "texture_types.h"

RT_DEVICE real3 UnpackTexel(uint t) {
  return make_real3((real)(t & 255u), (real)((t >> 8) & 255u), (real)((t >> 16) & 255u));
}

// The texel in column x, row y (row 0 on top), clamped to the image.
RT_DEVICE real3 FetchTexel(RT_GLOBAL const uint* texels, RT_GLOBAL const TextureDesc* t, int x,
                           int y) {
  x = x < 0 ? 0 : (x >= t->width ? t->width - 1 : x);
  y = y < 0 ? 0 : (y >= t->height ? t->height - 1 : y);
  int i = y * t->width + x;
  if (t->hdr) {
    RT_GLOBAL const uint* p = texels + t->first_texel + 3 * i;
    return make_real3((real)as_float(p[0]), (real)as_float(p[1]), (real)as_float(p[2]));
  }
  return UnpackTexel(texels[t->first_texel + i]);
}

// u runs along the rows from the left edge, v down the columns from the top edge; the
// image spans [0, 1]^2. Nearest takes the texel whose square contains (u W, v H).
RT_DEVICE real3 LookupNearest(RT_GLOBAL const uint* texels, RT_GLOBAL const TextureDesc* t,
                              real2 uv) {
  return FetchTexel(texels, t, (int)floor(uv.x * (real)t->width),
                    (int)floor(uv.y * (real)t->height));
}

// Bilinear interpolation between texel (i, j) and its right and lower neighbours, where
// (i, j) = floor(u W, v H) and the weights are the fractional parts: texel (i, j) counts
// as sampled at (i, j), not at its centre (i + 1/2, j + 1/2). This is the convention of
// the course's images (centres give MAE 4.1 on cube_wall, this 0.23).
RT_DEVICE real3 LookupBilinear(RT_GLOBAL const uint* texels, RT_GLOBAL const TextureDesc* t,
                               real2 uv) {
  real fx = uv.x * (real)t->width, fy = uv.y * (real)t->height;
  real x0 = floor(fx), y0 = floor(fy);
  real a = fx - x0, b = fy - y0;
  int x = (int)x0, y = (int)y0;
  real3 top = FetchTexel(texels, t, x, y) * (1.0f - a) + FetchTexel(texels, t, x + 1, y) * a;
  real3 bottom =
      FetchTexel(texels, t, x, y + 1) * (1.0f - a) + FetchTexel(texels, t, x + 1, y + 1) * a;
  return top * (1.0f - b) + bottom * b;
}

RT_DEVICE real3 LookupImage(RT_GLOBAL const uint* texels, RT_GLOBAL const TextureDesc* t,
                            real2 uv) {
  return t->interpolation == RT_INTERP_BILINEAR ? LookupBilinear(texels, t, uv)
                                                : LookupNearest(texels, t, uv);
}

#endif  // RT_IMAGE_TEXTURE_H
