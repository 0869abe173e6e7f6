// Every feature bit of the renderer, in one place. The host derives the set a scene
// needs (scene_features in src/prepare/flat_scene.cpp); the kernel is compiled with RT_KERNEL_FEATURES set
// to that set, so code for an absent feature is removed by the compiler. The CPU reference reads
// the same bits at run time from the scene header. A bit that is on when the scene does
// not need it never changes the image, only the speed.
#ifndef RT_FEATURES_H
#define RT_FEATURES_H

#define RT_FEATURE_SPHERES (1 << 0)          // Sphere objects (ellipsoids through transforms).
#define RT_FEATURE_TRIANGLES (1 << 1)        // Meshes and Triangle objects.
#define RT_FEATURE_TRANSFORMS (1 << 2)       // Objects whose transform is not the identity.
#define RT_FEATURE_SMOOTH (1 << 3)           // Meshes with shadingMode="smooth".
#define RT_FEATURE_POINT_LIGHTS (1 << 4)     // PointLight.
#define RT_FEATURE_AREA_LIGHTS (1 << 5)      // AreaLight (square or parallelogram).
#define RT_FEATURE_MIRROR (1 << 6)           // type="mirror".
#define RT_FEATURE_CONDUCTOR (1 << 7)        // type="conductor" (complex-index Fresnel).
#define RT_FEATURE_DIELECTRIC (1 << 8)       // type="dielectric": refraction, Fresnel, Beer.
#define RT_FEATURE_ROUGHNESS (1 << 9)        // Roughness > 0: glossy reflection.
#define RT_FEATURE_DEPTH_OF_FIELD (1 << 10)  // ApertureSize > 0.
#define RT_FEATURE_MOTION_BLUR (1 << 11)     // MotionBlur on any object.
#define RT_FEATURE_MULTISAMPLE (1 << 12)     // More than one sample per pixel: jittered.
#define RT_FEATURE_TEXTURES (1 << 13)  // Textures: images, Perlin, checkerboard, bump/normal maps.
#define RT_FEATURE_DIRECTIONAL_LIGHTS (1 << 14)  // DirectionalLight.
#define RT_FEATURE_SPOT_LIGHTS (1 << 15)         // SpotLight.
#define RT_FEATURE_BRDF (1 << 16)  // A material with a BRDF other than the original Blinn-Phong.
#define RT_FEATURE_MESH_LIGHTS (1 << 17)    // LightMesh: an emitting triangle mesh (hw6).
#define RT_FEATURE_SPHERE_LIGHTS (1 << 18)  // LightSphere: an emitting sphere or ellipsoid (hw6).
#define RT_FEATURE_ENVIRONMENT_LIGHT (1 << 19)  // SphericalDirectionalLight (an HDR environment).
// A camera with <Renderer>PathTracing (integrator/path.h).
#define RT_FEATURE_PATH_TRACING (1 << 20)
// A mesh whose rays keep the world's direction: not transformed, or translated only
// (RT_INSTANCE_TRANSLATION). Its triangle ray's direction part is then made once per ray.
#define RT_FEATURE_WORLD_MESHES (1 << 21)
#define RT_FEATURE_ALL ((1 << 22) - 1)

// Light and material type tags are their feature bits, so the features a scene needs are
// the OR of the types it uses, and a new type is one new bit here (with its code in
// cl/light/ or cl/material/). Plain Blinn-Phong needs no feature.
#define RT_LIGHT_POINT RT_FEATURE_POINT_LIGHTS
#define RT_LIGHT_AREA RT_FEATURE_AREA_LIGHTS
#define RT_LIGHT_DIRECTIONAL RT_FEATURE_DIRECTIONAL_LIGHTS
#define RT_LIGHT_SPOT RT_FEATURE_SPOT_LIGHTS
#define RT_LIGHT_MESH RT_FEATURE_MESH_LIGHTS
#define RT_LIGHT_SPHERE RT_FEATURE_SPHERE_LIGHTS
// Either kind of object light: geometry that emits, found by a ray (cl/light/emission.h).
#define RT_FEATURE_OBJECT_LIGHTS (RT_FEATURE_MESH_LIGHTS | RT_FEATURE_SPHERE_LIGHTS)
#define RT_LIGHT_ENVIRONMENT RT_FEATURE_ENVIRONMENT_LIGHT
#define RT_MATERIAL_PLAIN 0
#define RT_MATERIAL_MIRROR RT_FEATURE_MIRROR
#define RT_MATERIAL_CONDUCTOR RT_FEATURE_CONDUCTOR
#define RT_MATERIAL_DIELECTRIC RT_FEATURE_DIELECTRIC

#ifdef __OPENCL_C_VERSION__
#ifndef RT_KERNEL_FEATURES
#define RT_KERNEL_FEATURES RT_FEATURE_ALL
#endif
// A compile-time constant in the kernel: untaken branches vanish. The scene is named (and
// so counts as used) though not read, as a function that reads it only through RT_HAS
// would otherwise have an unused parameter in the kernel.
#define RT_HAS(scene, feature) ((void)(scene), (RT_KERNEL_FEATURES & (feature)) != 0)
// For #if around whole functions that only one feature calls: the kernel compiles them
// only when the scene needs the feature.
#define RT_COMPILED(feature) ((RT_KERNEL_FEATURES & (feature)) != 0)
#else
// A run-time test on the CPU, against the bits stored in the scene header.
#define RT_HAS(scene, feature) (((scene)->header->features & (feature)) != 0)
#define RT_COMPILED(feature) 1
#endif

#endif  // RT_FEATURES_H
