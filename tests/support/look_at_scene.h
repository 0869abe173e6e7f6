// A second scene for the loader's tests (tests/scene/loader/): a lookAt camera and one
// sphere, with the camera's direction and tone mapping, the lights, the BRDFs and the
// material's attributes left to each test, which loads it or expects the one-line error.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "scene/scene.h"
#include "support/test_scene.h"

namespace rt::test {

// CAMERA, TONEMAP, LIGHTS, BRDFS and MATERIAL are filled in from LookAtParts.
inline const char* const kLookAtTemplate = R"(<Scene>
  <Cameras><Camera id="1" type="lookAt"><Position>0 0 5</Position>CAMERA<Up>0 1 0</Up>
    <FovY>45</FovY><NearDistance>1</NearDistance><ImageResolution>8 8</ImageResolution>
    <ImageName>out.exr</ImageName>TONEMAP</Camera></Cameras>
  <Lights>LIGHTS</Lights>
  BRDFS
  <Materials><Material id="1" MATERIAL><AmbientReflectance>1 1 1</AmbientReflectance>
    <DiffuseReflectance>0.5 0.5 0.5</DiffuseReflectance>
    <SpecularReflectance>0.25 0.25 0.25</SpecularReflectance><PhongExponent>3</PhongExponent>
  </Material></Materials>
  <VertexData>0 0 0</VertexData>
  <Objects><Sphere id="1"><Material>1</Material><Center>1</Center><Radius>1</Radius></Sphere>
  </Objects>
</Scene>)";

struct LookAtParts {
  std::string camera = "<GazePoint>0 0 0</GazePoint>", tonemap, lights, brdfs, material;
};

// The scene of `p`, written to a file of its own; returns its path.
inline std::string write_look_at(const LookAtParts& p) {
  const std::string xml = edited(kLookAtTemplate, {{"CAMERA", p.camera},
                                                   {"TONEMAP", p.tonemap},
                                                   {"LIGHTS", p.lights},
                                                   {"BRDFS", p.brdfs},
                                                   {"MATERIAL", p.material}});
  std::string path = testing::TempDir() + "look_at_" + std::to_string(getpid()) + ".xml";
  std::ofstream(path) << xml;
  return path;
}

inline SceneDesc load_look_at(const LookAtParts& p) {
  std::string path = write_look_at(p);
  SceneDesc s = load_scene(path);
  std::remove(path.c_str());
  return s;
}

// Loading the scene of `p` fails in one line that contains `fragment`.
inline void expect_look_at_error(const LookAtParts& p, const std::string& fragment) {
  const std::string path = write_look_at(p);
  expect_load_error(path, {fragment});
  std::remove(path.c_str());
}

}  // namespace rt::test
