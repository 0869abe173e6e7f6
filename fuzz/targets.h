// The fuzzed entry points, shared by the libFuzzer executables (fuzz/fuzzer.cpp) and the
// unit tests that replay every input kept in fuzz/regressions/ (tests/fuzz/regression_test.cpp,
// tests/fuzz/fuzz_replay_test.cpp).
// Each returns normally for any input the program handles as it should (loaded, or refused
// with one rt::InputError line); anything else escapes as an exception or a sanitizer report.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rt {

// The bytes are a scene file. It is loaded (relative PLY paths resolve to a folder holding a
// small valid m.ply), flattened, and every camera set up, as a render would start.
void fuzz_scene(const uint8_t* data, size_t size);

// The bytes are a PLY file.
void fuzz_ply(const uint8_t* data, size_t size);

// The bytes are a command line: arguments separated by NUL bytes.
void fuzz_cli(const uint8_t* data, size_t size);

// The bytes are an image file named in.png, in.jpg, in.exr or in.hdr, read as a texture or
// environment map is (read_any_image; PNG and JPEG are told apart by content, not name).
// fuzz/image_targets.cpp.
void fuzz_png(const uint8_t* data, size_t size);
void fuzz_jpeg(const uint8_t* data, size_t size);
void fuzz_exr(const uint8_t* data, size_t size);
void fuzz_hdr(const uint8_t* data, size_t size);

// The bytes are a model file named in.obj, or in.gltf (in.glb when it starts with the magic
// "glTF"), imported by rtconvert (Assimp, then the course's glTF extras) and written out as a
// course scene. fuzz/convert_targets.cpp; built only where rtconvert is (libassimp-dev), and Assimp
// itself is not instrumented.
void fuzz_obj(const uint8_t* data, size_t size);
void fuzz_gltf(const uint8_t* data, size_t size);

}  // namespace rt
