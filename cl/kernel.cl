// The OpenCL entry point: one work-item per pixel, running a slice of that pixel's
// samples. All of the maths lives in the shared headers.
#include "film.h"

__kernel void render(__global const SceneHeader* header, __global const Material* materials,
                     __global const Instance* instances, __global const BvhNode* nodes,
                     __global const Triangle* triangles, __global const TriangleNormals* normals,
                     __global const PointLight* point_lights, __global const AreaLight* area_lights,
                     __global const TextureDesc* textures, __global const uint* texels,
                     __global const InstanceTextures* instance_textures,
                     __global const TriangleUV* triangle_uvs,
                     int row_begin, int sample_begin, int sample_end, __global PixelAccum* accum,
                     __global PrimaryInfo* primary) {
  int x = (int)get_global_id(0);
  int y = row_begin + (int)get_global_id(1);
  if (x >= header->camera.width || y >= header->camera.height) return;
  SceneData sd;
  sd.header = header;
  sd.materials = materials;
  sd.instances = instances;
  sd.nodes = nodes;
  sd.triangles = triangles;
  sd.normals = normals;
  sd.point_lights = point_lights;
  sd.area_lights = area_lights;
  sd.textures = textures;
  sd.texels = texels;
  sd.instance_textures = instance_textures;
  sd.triangle_uvs = triangle_uvs;
  int pixel = y * header->camera.width + x;
  AccumulatePixel(&sd, x, y, sample_begin, sample_end, &accum[pixel], &primary[pixel]);
}
