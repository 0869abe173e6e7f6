// The fuzzed entry points, shared by the libFuzzer executables (fuzz/fuzzer.cpp) and the
// unit test that replays every input kept in fuzz/regressions/ (tests/fuzz/regression_test.cpp).
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

}  // namespace rt
