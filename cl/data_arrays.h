// The scene's device arrays, named once. Every place that must list them (the SceneData
// struct, the kernel's parameters and their fill, the host vectors of FlatScene and its
// view(), the empty-array padding, the uploads and their kernel arguments, the memory
// check and the layout check) expands this list instead of spelling the arrays out, so
// a new array is one line here and no positional argument can drift out of step.
// (Cycles keeps its kernel data the same way, in src/kernel/data_arrays.h.)
//
// The list is a function-like macro rather than a file included several times because
// cmake/embed_kernel.cpp inlines each header once. The scene header is not an array and
// is passed first, before these.
#ifndef RT_DATA_ARRAYS_H
#define RT_DATA_ARRAYS_H

// RT_DATA_ARRAY(Type, name): one array `name` of `Type`, in kernel-argument order.
// instance_lights: per instance, the index in `lights` of the object light it is, or -1;
// light_cdf: the mesh lights' cumulative triangle areas (see Light in scene_types.h).
#define RT_DATA_ARRAYS(RT_DATA_ARRAY)                \
  RT_DATA_ARRAY(Material, materials)                 \
  RT_DATA_ARRAY(Instance, instances)                 \
  RT_DATA_ARRAY(BvhNode, nodes)                      \
  RT_DATA_ARRAY(Triangle, triangles)                 \
  RT_DATA_ARRAY(TriangleBlock, triangle_blocks)      \
  RT_DATA_ARRAY(TriangleNormals, normals)            \
  RT_DATA_ARRAY(Light, lights)                       \
  RT_DATA_ARRAY(TextureDesc, textures)               \
  RT_DATA_ARRAY(uint, texels)                        \
  RT_DATA_ARRAY(InstanceTextures, instance_textures) \
  RT_DATA_ARRAY(TriangleUV, triangle_uvs)            \
  RT_DATA_ARRAY(int, instance_lights)                \
  RT_DATA_ARRAY(float, light_cdf)                    \
  RT_DATA_ARRAY(float4, env_texels)                  \
  RT_DATA_ARRAY(float, env_marginal_cdf)             \
  RT_DATA_ARRAY(float, env_conditional_cdf)

// Structs whose size both sides must agree on besides the arrays' element types: the
// layout check (rt_sizes in cl/kernel.cl, scene_layout() on the host) covers all of them.
#define RT_LAYOUT_TYPES(RT_LAYOUT_TYPE) \
  RT_LAYOUT_TYPE(float3)                \
  RT_LAYOUT_TYPE(SceneHeader)           \
  RT_LAYOUT_TYPE(Camera)                \
  RT_LAYOUT_TYPE(PixelAccum)            \
  RT_LAYOUT_TYPE(PrimaryInfo)

#endif  // RT_DATA_ARRAYS_H
