// The flattened scene as both devices read it. The host fills these arrays
// (src/flat_scene.cpp) and uploads them unchanged; every struct is a multiple of 16 bytes
// with float3/float4 members first, so C++ and OpenCL C lay them out identically
// (checked by static_asserts in src/flat_scene.cpp and, on the device, by rt_sizes).
#ifndef RT_SCENE_TYPES_H
#define RT_SCENE_TYPES_H

#include "compat.h"
#include "data_arrays.h"
#include "features.h"
#include "texture/texture_types.h"

// A material's parameters as the file gives them; cl/material/material.h evaluates them
// at a surface point into the Bsdf that shading reads. `type` is an RT_MATERIAL_* tag.

typedef struct Material {
  float3 ambient;
  float3 diffuse;
  float3 specular;
  float3 mirror;
  float3 absorption;  // Beer's law coefficient per unit length (AbsorptionCoefficient).
  float phong_exponent;
  float refraction_index;
  float absorption_index;  // Imaginary part of a conductor's index (AbsorptionIndex).
  float roughness;
  int type;
  int unlit;  // 1: shows `diffuse` as radiance, unshaded (a replace_all texture set it).
  int pad1, pad2;
} Material;

// Every light of the scene in one array, tagged by `type` (an RT_LIGHT_* tag); each type
// reads the members it documents and cl/light/ samples it. Point lights come first, then
// area lights, so the direct light at a point is summed in the order it always was.
typedef struct Light {
  float3 position;  // Point: the light's position. Area: the parallelogram's corner.
  float3 edge1;     // Area: the points are position + s * edge1 + t * edge2, s, t in [0, 1).
  float3 edge2;
  float3 normal;                 // Area: unit normal (the light emits from both faces).
  float3 emission;               // Point: intensity (power per unit solid angle). Area: radiance.
  float area;                    // Area: |edge1 x edge2|.
  float param0, param1, param2;  // Type-specific scalars (for example a spot's cone angles).
  // Keys the light's random numbers (cl/light/light.h); numbered within the lights that
  // draw any, so adding a light of another type does not change another light's samples.
  int sample_index;
  int type;
  int index;  // Type-specific index (for example a texture or an emitting instance).
  int pad0;
} Light;

#define RT_LENS_SQUARE 0
#define RT_LENS_DISK 1
#define RT_FILTER_BOX 0
#define RT_FILTER_GAUSSIAN 1

typedef struct Camera {
  float3 position;
  float3 u, v, w;  // Right, up, and backwards (w = -gaze), orthonormal.
  float left, right, bottom, top;
  float near_distance;
  float aperture;        // Edge of the square lens (or diameter of the disk lens).
  float focus_distance;  // Distance to the focal plane along the gaze.
  int lens;
  int width, height;
  int samples;  // Samples per pixel.
  int strata;   // sqrt(samples) when it is a perfect square, else 0 (no strata).
} Camera;

#define RT_INSTANCE_MESH 0
#define RT_INSTANCE_SPHERE 1

#define RT_INSTANCE_TRANSFORMED 1
#define RT_INSTANCE_SMOOTH 2
#define RT_INSTANCE_MOVING 4

// One object of the top level: a mesh's bottom-level BVH or the unit sphere, seen
// through an affine transform and moving by time * motion over the shutter.
typedef struct Instance {
  float4 world_to_object[3];  // Rows of the inverse transform.
  float4 object_to_world[3];  // Rows of the transform (at time 0).
  float3 motion;              // World-space translation at time 1.
  int kind;
  int blas_root;  // Node index of the mesh's BVH root (meshes only).
  int material;
  int flags;
} Instance;

// A BVH node: leaf when count > 0 (primitives first..first+count-1), otherwise an
// interior node whose children are first and first+1, split along axis -count.
typedef struct BvhNode {
  float lo[3];
  int first;
  float hi[3];
  int count;
} BvhNode;

typedef struct Triangle {
  float3 v0, v1, v2;
} Triangle;

typedef struct TriangleNormals {
  float3 n0, n1, n2;
} TriangleNormals;

// The deepest MaxRecursionDepth accepted; it bounds the integrator's ray stack.
#define RT_MAX_DEPTH 30

#define RT_FLAG_CULL_BACK_FACES 1
#define RT_FLAG_BACKGROUND_ON_SECONDARY_MISS 2
#define RT_FLAG_FRESNEL_CHOICE 4  // Dielectrics follow one ray, chosen by Fresnel.

typedef struct SceneHeader {
  Camera camera;
  float3 background;
  float3 ambient_light;
  float shadow_epsilon;  // The scene's ShadowRayEpsilon, added along the normal.
  float intersection_epsilon;
  int max_depth;
  int tlas_root;
  int num_lights;
  int background_texture;  // Index of the replace_background texture, or -1.
  int num_instances;
  int features;
  uint seed;
  int filter;
  float filter_sigma;  // Gaussian filter's standard deviation, in pixels.
  int flags;
} SceneHeader;

// The arrays of one scene, passed by pointer to every stage (compare Cycles'
// KernelGlobals). In OpenCL it lives in private memory and points to global buffers.
#define RT_SCENE_DATA_MEMBER(Type, name) RT_GLOBAL const Type* name;
typedef struct SceneData {
  RT_GLOBAL const SceneHeader* header;
  RT_DATA_ARRAYS(RT_SCENE_DATA_MEMBER)
} SceneData;
#undef RT_SCENE_DATA_MEMBER

#endif  // RT_SCENE_TYPES_H
