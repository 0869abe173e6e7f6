// A folder private to one fuzzing process, made on first use and removed at its end: the
// readers under test take a path, not bytes, so each input is written to a file here first.
// /dev/shm (a tmpfs) is preferred where it exists, so a million inputs cost no disk writes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rt {

// The folder's path (no trailing slash).
const std::string& fuzz_scratch_dir();

// Writes the bytes to fuzz_scratch_dir()/name, replacing what was there; returns its path.
std::string fuzz_scratch_file(const std::string& name, const uint8_t* data, size_t size);

}  // namespace rt
