// The flattened scene as both devices read it. The host fills these arrays
// (src/prepare/flat_scene.cpp) and uploads them unchanged; every struct is a multiple of 16 bytes
// with float3/float4 members first, so C++ and OpenCL C lay them out identically
// (checked by static_asserts in src/prepare/flat_scene.cpp and, on the device, by rt_sizes).
#ifndef RT_SCENE_TYPES_H
#define RT_SCENE_TYPES_H

#include "bvh/simd.h"
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
  int brdf;   // RT_BRDF_* model of cl/material/brdf.h; 0, the original Blinn-Phong, is the default.
  int brdf_flags;  // RT_BRDF_NORMALIZED, RT_BRDF_KD_FRESNEL.
} Material;

// Every light of the scene in one array, tagged by `type` (an RT_LIGHT_* tag); each type
// reads the members it documents and cl/light/ samples it. The host orders them point
// lights, area lights, the directional, spot and environment lights in file order, then
// the object lights (src/prepare/world_frame.cpp, flat_object_lights.cpp); direct lighting
// sums in this order, which fixes the last bit of its result.
typedef struct Light {
  float3 position;  // Point, spot: the light's position. Area: the parallelogram's corner.
  float3 edge1;     // Area: the points are position + s * edge1 + t * edge2, s, t in [0, 1).
  float3 edge2;
  // Area: unit normal (the light emits from both faces). Directional: the unit direction
  // the light travels in. Spot: the unit axis of its cone.
  float3 normal;
  // Point, spot: intensity (power per unit solid angle). Area, directional, mesh, sphere:
  // radiance.
  float3 emission;
  // The per-type parameters: each type's own meaning of these slots has a name below
  // (RT_LIGHT_SURFACE_AREA and the others), by which both the host and the kernel reach it.
  float scalar[4];
  // Keys the light's random numbers (cl/light/light.h); numbered within the lights that
  // draw any, so adding a light of another type does not change another light's samples.
  int sample_index;
  int type;
  int slot[6];  // Per-type indices, named below like `scalar`; the last is unused.
} Light;

// The per-type parameters of a Light, by name, for a pointer to it: valid as an lvalue in
// C++ and in OpenCL C, so the host fills and the kernel reads the same names.
// Area light: |edge1 x edge2|. Mesh light: its world-space area.
#define RT_LIGHT_SURFACE_AREA(light) ((light)->scalar[0])
// Directional and environment: the length of the shadow segment, longer than the scene's
// bounding-box diagonal, so it leaves the scene from any point inside.
#define RT_LIGHT_REACH(light) ((light)->scalar[1])
// Mesh and sphere lights: the index of the emitting instance.
#define RT_LIGHT_INSTANCE(light) ((light)->slot[0])
// Spot: cos(FalloffAngle / 2), inside which it is a point light, and cos(CoverageAngle / 2),
// outside which it sends nothing.
#define RT_SPOT_COS_FALLOFF(light) ((light)->scalar[1])
#define RT_SPOT_COS_COVERAGE(light) ((light)->scalar[2])
// Sphere light: |det| of the instance's object-to-world transform (its volume scale).
#define RT_SPHERE_VOLUME_SCALE(light) ((light)->scalar[1])
// Mesh light: its triangles are triangles[first .. first + count - 1], and
// light_cdf[cdf .. cdf + count - 1] their cumulative world-space areas over its area.
#define RT_MESH_FIRST(light) ((light)->slot[1])
#define RT_MESH_COUNT(light) ((light)->slot[2])
#define RT_MESH_CDF(light) ((light)->slot[3])
// Environment: the integral its importance-sampling density was built from (0: the map is
// black and sends nothing); the map's width and height (whole numbers); its mapping,
// RT_ENV_LATLONG or RT_ENV_PROBE (cl/light/environment_map.h); how it is sampled
// (RT_ENV_SAMPLE_*).
#define RT_ENV_INTEGRAL(light) ((light)->scalar[0])
#define RT_ENV_WIDTH(light) ((light)->scalar[2])
#define RT_ENV_HEIGHT(light) ((light)->scalar[3])
#define RT_ENV_MAPPING(light) ((light)->slot[0])
#define RT_ENV_SAMPLING(light) ((light)->slot[4])

#define RT_LENS_SQUARE 0
#define RT_LENS_DISK 1
#define RT_FILTER_BOX 0
#define RT_FILTER_GAUSSIAN 1

typedef struct Camera {
  float3 position;
  float3 u, v, w;  // Right, up, and backwards (w = -gaze), orthonormal.
  // The course's camera rays (RT_FLAG_COURSE_CAMERA): its eye, film corner q and u, v in
  // world space, each rounded as its float arithmetic rounds them (src/prepare/course_camera.cpp).
  float3 course_eye, course_q, course_u, course_v;
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
// Set with RT_INSTANCE_TRANSFORMED when world_to_object's linear part is exactly the
// identity (1.0f on the diagonal, +0.0f elsewhere): the transform moves origins only, and
// every such instance turns a direction into the same vector (cl/bvh/bvh.h shares its setup).
#define RT_INSTANCE_TRANSLATION 8

// One object of the top level: a mesh's bottom-level BVH or the unit sphere, seen
// through an affine transform and moving by time * motion over the shutter.
typedef struct Instance {
  float4 world_to_object[3];  // Rows of the inverse transform.
  float4 object_to_world[3];  // Rows of the transform (at time 0).
  float3 motion;              // World-space translation at time 1.
  // Where procedural textures are evaluated, added to the point the course defines them at:
  // a mesh's vertices are stored relative to a point of the mesh (its frame origin, this
  // vector), a sphere's world-space point relative to the camera (the camera's position).
  float3 texture_origin;
  int kind;
  int blas_root;  // Node index of the mesh's BVH root (meshes only).
  int material;
  int flags;
} Instance;

// A node of the wide BVH: the boxes of up to RT_BVH_WIDTH children (the width the host
// built this device's arrays with, src/bvh/bvh_lanes.h), one lane per child,
// stored as one vector per bound (structure of arrays) so one node test checks every child
// at once with aligned vector loads. child[i] is a node index (>= 0), RT_BVH_EMPTY for an
// unused lane, or a leaf reference made by RtLeafRef (count triangles from the block
// `first` of triangle_blocks at the bottom level, or one instance at the top level).
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

// RT_BVH_WIDTH triangles of one bottom-level leaf, structure of arrays, for the block test
// (cl/geometry/shapes.h, IntersectTriangleBlock): v[3 * k + a] holds axis a of vertex k, lane i the
// triangle `first + i` of `triangles`. A leaf of n triangles is ceil(n / RT_BVH_WIDTH)
// consecutive blocks; lanes past its end hold an all-zero triangle, which the watertight
// test always rejects (its determinant is exactly 0). The bottom-level leaf references
// (RtLeafRef) count triangles from their first block (src/bvh/triangle_blocks.cpp).
typedef struct TriangleBlock {
  LaneFloat v[9];
  int first;
  int pad[3];
} TriangleBlock;

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
// Sphere lights deliver L / pdf in world space; otherwise L times their object-space solid
// angle, the course's convention (cl/light/sphere_light.h).
#define RT_FLAG_EXACT_ELLIPSOID_LIGHTS 8
// The camera's renderer (hw6 <Renderer>, per camera): the path tracer of
// cl/integrator/path.h instead of the ray tree, and its <RendererParams>.
#define RT_FLAG_PATH_TRACING 16
#define RT_FLAG_NEXT_EVENT 32           // NextEventEstimation: sample the lights at each bounce.
#define RT_FLAG_IMPORTANCE_SAMPLING 64  // ImportanceSampling: cosine-weighted bounces.
#define RT_FLAG_RUSSIAN_ROULETTE 128    // RussianRoulette: end paths by their throughput.
// --russian-roulette unbiased: a path the roulette ends drops its last vertex's light.
#define RT_FLAG_UNBIASED_ROULETTE 256
// --reflection-offset facing: a mirror or conductor seen from behind reflects from the side
// the ray came from, not from the side of its normal as modelled (cl/material/mirror.h).
#define RT_FLAG_FACING_REFLECTION 512
// --ray-offset robust: spawned rays start the scene's epsilon plus a few ulps of the
// surface's scale off it (cl/geometry/ray.h), not the scene's epsilon alone as the course's rays
// do.
#define RT_FLAG_ROBUST_OFFSET 1024
#define RT_ROBUST_OFFSET(sd) (((sd)->header->flags & RT_FLAG_ROBUST_OFFSET) != 0)
// Camera rays as the course's renderer computes them: in world space, in float
// (cl/camera/camera.h, CourseCameraDirection).
#define RT_FLAG_COURSE_CAMERA 2048
// Shadow rays leave along the geometric normal instead of the course's shading normal.
#define RT_FLAG_GEOMETRIC_OFFSET 4096
// --hit-point ray: the surface point is the ray's origin + t * direction, as the course's
// renderer forms it, not rebuilt from the primitive (cl/geometry/surface.h).
#define RT_FLAG_RAY_HIT_POINT 8192
// --path-estimator mis: the path tracer weighs light samples against BSDF samples (power
// heuristic), plays pbrt-v4's roulette and follows one lobe per bounce (cl/integrator/path.h).
#define RT_FLAG_MIS 16384
// --sampler sobol: every random dimension is an Owen-scrambled Sobol point (cl/sampling/sobol.h)
// instead of a hash with jittered strata on the camera's (cl/sampling/sampler.h).
#define RT_FLAG_SOBOL_SAMPLER 32768
// The bits set_camera sets per camera.
#define RT_FLAG_PATH_MASK                                                    \
  (RT_FLAG_PATH_TRACING | RT_FLAG_NEXT_EVENT | RT_FLAG_IMPORTANCE_SAMPLING | \
   RT_FLAG_RUSSIAN_ROULETTE)

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
  int environment;  // Index in the lights of the environment light (at most one), or -1.
} SceneHeader;

// The arrays of one scene, passed by pointer to every stage (compare Cycles'
// KernelGlobals). In OpenCL it lives in private memory and points to global buffers.
#define RT_SCENE_DATA_MEMBER(Type, name) RT_GLOBAL const Type* name;
typedef struct SceneData {
  RT_GLOBAL const SceneHeader* header;
  RT_DATA_ARRAYS(RT_SCENE_DATA_MEMBER)
#if RT_GPU_FORMS
  // The work-item's one BVH stack (cl/bvh/bvh.h), made by the kernel's entry: its closest-hit
  // and shadow traversals never overlap, and on a GPU each inlined traversal's own array
  // would take its own private memory.
  RT_PRIVATE int* bvh_stack;
#endif
} SceneData;
#undef RT_SCENE_DATA_MEMBER

#endif  // RT_SCENE_TYPES_H
