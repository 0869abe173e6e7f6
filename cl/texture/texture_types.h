// The textures of a scene as both devices read them: one array of texels shared by every
// image (packed 8-bit RGB, or float RGB for HDR images), one descriptor per TextureMap, and per-triangle texture
// coordinates parallel to the triangle array. Layout rules as in scene_types.h.
#ifndef RT_TEXTURE_TYPES_H
#define RT_TEXTURE_TYPES_H

#include "../compat.h"

#define RT_TEXTURE_IMAGE 0
#define RT_TEXTURE_PERLIN 1
#define RT_TEXTURE_CHECKERBOARD 2

// What a texture's value does at a hit (the course's DecalMode).
#define RT_DECAL_REPLACE_KD 0
#define RT_DECAL_BLEND_KD 1
#define RT_DECAL_REPLACE_KS 2
#define RT_DECAL_REPLACE_BACKGROUND 3
#define RT_DECAL_REPLACE_NORMAL 4
#define RT_DECAL_BUMP_NORMAL 5
#define RT_DECAL_REPLACE_ALL 6

#define RT_INTERP_NEAREST 0
#define RT_INTERP_BILINEAR 1

#define RT_NOISE_LINEAR 0  // (noise + 1) / 2
#define RT_NOISE_ABSVAL 1  // |noise|

// The most textures one object may list (the course's files use two).
#define RT_MAX_OBJECT_TEXTURES 4

typedef struct TextureDesc {
  float3 black;  // Checkerboard colours (BlackColor, WhiteColor), on the 0..1 scale.
  float3 white;
  int type;
  int decal;
  int interpolation;
  int first_texel;  // Image: index of its top-left texel in the texel array.
  int width, height;
  float normalizer;  // Image values are divided by it (the course's default 255).
  float bump_factor;
  float noise_scale;
  int noise_conversion;
  float checker_scale;
  float checker_offset;
  // 1: the image is high-dynamic-range (EXR, RGBE) and its texels are three floats each
  // (the bits of R, G, B, as uints) in the texel array; 0: one packed 8-bit RGB uint.
  int hdr;
} TextureDesc;

// The texture maps an object lists, by index into the descriptors; -1 ends the list.
typedef struct InstanceTextures {
  int ids[RT_MAX_OBJECT_TEXTURES];
} InstanceTextures;

// Texture coordinates of a triangle's corners, in the order of its vertices.
typedef struct TriangleUV {
  float2 uv0, uv1, uv2;
  float2 pad;
} TriangleUV;

#endif  // RT_TEXTURE_TYPES_H
