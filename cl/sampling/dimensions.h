// Every random dimension the renderer draws, in one table. A sample's numbers are hashes of
// (pixel, sample, dimension, seed) (cl/sampling/sampler.h), so two draws that share a
// dimension share their number: the table keeps every dimension apart, and keeps the same
// draw on the same dimension in both integrators (a mirror's glossy sample in the ray tree
// and in the path tracer, for instance).
//
// The camera sample draws the absolute dimensions below. Every ray after it has a key (the
// camera ray's is RT_DIM_FIRST_FREE; a child's is HashCombine(parent's key, RT_CHILD_*) in
// the ray tree, HashCombine(vertex key, RT_PATH_NEXT_VERTEX + lobe) in the path tracer), and
// draws dimension HashCombine(key, offset) for the offsets below (RaySample1D, RaySample2D).
#ifndef RT_SAMPLING_DIMENSIONS_H
#define RT_SAMPLING_DIMENSIONS_H

// The camera sample, in the order the course names its dimensions (2D ones take two).
#define RT_DIM_PIXEL 0
#define RT_DIM_LENS 2
#define RT_DIM_TIME 4
// The key of the camera ray: later dimensions are keyed by the ray's place in its tree.
#define RT_DIM_FIRST_FREE 5

// The second coordinate of a 2D dimension is drawn from this dimension.
#define RT_DIM_SECOND(dimension) ((dimension) ^ 0x68bc21ebu)

// Offsets from a ray's key.
// The dielectric's Fresnel choice between its reflected and refracted ray.
#define RT_DIM_FRESNEL_CHOICE 4u
// The 2D sample of the first light; light i draws RT_OFFSET_LIGHT + i (LightSampleOffset).
#define RT_OFFSET_LIGHT 0x1000u
// The glossy perturbation of a reflected (or, keyed by RT_KEY_FROSTED_REFRACTION, a
// refracted) direction.
#define RT_DIM_GLOSSY 0x2000u
// The path tracer's vertex: the reflection model's direction, the choice between the
// reflection model and the delta lobes, and Russian roulette.
#define RT_DIM_BSDF_DIRECTION 0x3000u
#define RT_DIM_BSDF_LOBE 0x3001u
#define RT_DIM_RUSSIAN_ROULETTE 0x3002u

// Keys derived from a ray's key: HashCombine(key, one of these).
// The ray tree's children.
#define RT_CHILD_REFLECTED 1u
#define RT_CHILD_REFRACTED 2u
// The refracted direction's glossy sample, apart from the reflected direction's.
#define RT_KEY_FROSTED_REFRACTION 3u
// The path tracer's next vertex, plus the lobe taken (RT_LOBE_*), so no two vertices of a
// path tree draw the same numbers.
#define RT_PATH_NEXT_VERTEX 0x70617468u

#endif  // RT_SAMPLING_DIMENSIONS_H
