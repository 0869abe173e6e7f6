// The flattened scene as both devices read it. The host fills these arrays
// (src/flatten.cpp) and uploads them unchanged; every struct is a multiple of 16 bytes
// with float3/float4 members first, so C++ and OpenCL C lay them out identically
// (checked by static_asserts in src/flatten.cpp).
#ifndef RT_SCENE_TYPES_H
#define RT_SCENE_TYPES_H

#include "compat.h"
#include "simd.h"

#define RT_MATERIAL_PLAIN 0
#define RT_MATERIAL_MIRROR 1
#define RT_MATERIAL_CONDUCTOR 2
#define RT_MATERIAL_DIELECTRIC 3

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
  int pad0, pad1, pad2;
} Material;

typedef struct PointLight {
  float3 position;
  float3 intensity;
} PointLight;

// A parallelogram corner + s * edge1 + t * edge2; the course's square lights are the
// special case of two orthogonal edges of length Size centred on Position.
typedef struct AreaLight {
  float3 corner;
  float3 edge1;
  float3 edge2;
  float3 normal;
  float3 radiance;
  float area;
  int pad0, pad1, pad2;
} AreaLight;

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

// A node of the wide BVH: the boxes of up to RT_BVH_WIDTH children, one lane per child,
// stored as one vector per bound (structure of arrays) so one node test checks every child
// at once with aligned vector loads. child[i] is a node index (>= 0), RT_BVH_EMPTY for an
// unused lane, or a leaf reference made by RtLeafRef (primitives first..first+count-1 of
// the triangles at the bottom level, or one instance at the top level).
#define RT_BVH_EMPTY (-1)
#define RT_BVH_LEAF_COUNT_BITS 4
#define RT_BVH_MAX_LEAF (1 << RT_BVH_LEAF_COUNT_BITS)
// Leaves address primitives below this index (the leaf reference packs it in 27 bits).
#define RT_BVH_MAX_PRIMITIVES ((1 << (31 - RT_BVH_LEAF_COUNT_BITS)) - 1)
#define RtLeafRef(first, count) (-2 - (((first) << RT_BVH_LEAF_COUNT_BITS) | ((count)-1)))
#define RtLeafFirst(ref) ((-2 - (ref)) >> RT_BVH_LEAF_COUNT_BITS)
#define RtLeafCount(ref) (((-2 - (ref)) & (RT_BVH_MAX_LEAF - 1)) + 1)

typedef struct RT_ALIGN_NODE BvhNode {
  LaneFloat bounds[6];  // lo x, y, z then hi x, y, z; lane i bounds child i.
  LaneInt child;
  LaneInt pad;  // Rounds the node to 128 (width 4) or 256 bytes (width 8): whole cache lines.
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
  int num_point_lights;
  int num_area_lights;
  int num_instances;
  int features;
  uint seed;
  int filter;
  float filter_sigma;  // Gaussian filter's standard deviation, in pixels.
  int flags;
} SceneHeader;

// The arrays of one scene, passed by pointer to every stage (compare Cycles'
// KernelGlobals). In OpenCL it lives in private memory and points to global buffers.
typedef struct SceneData {
  RT_GLOBAL const SceneHeader* header;
  RT_GLOBAL const Material* materials;
  RT_GLOBAL const Instance* instances;
  RT_GLOBAL const BvhNode* nodes;
  RT_GLOBAL const Triangle* triangles;
  RT_GLOBAL const TriangleNormals* normals;
  RT_GLOBAL const PointLight* point_lights;
  RT_GLOBAL const AreaLight* area_lights;
} SceneData;

#endif  // RT_SCENE_TYPES_H
