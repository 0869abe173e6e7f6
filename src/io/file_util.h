// Whole-file reads and atomic whole-file writes, the one way the program writes its outputs
// (images, moment files, the kernel cache).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rt {

// Reads the whole file into *data. Returns 0, or the errno of the failure (EISDIR for a
// directory); *data is then empty.
int read_file(const std::string& path, std::vector<uint8_t>* data);

// Writes `size` bytes to `path` atomically: a temporary file with a short random name
// (".rt-XXXXXX", so any valid final name fits) in the same directory, fsync, then a rename
// over `path`, so readers see the old file or the whole new one, never a part. Returns 0, or
// the errno of the failure; then no temporary file remains and `path` is untouched.
// While the temporary exists it is registered, so remove_pending_temporaries() (from a
// signal handler) can delete it.
int write_file_atomic(const std::string& path, const void* data, size_t size);

// Unlinks every temporary file an unfinished write_file_atomic holds. Async-signal-safe:
// called by the abort path of the signal handlers before _exit.
void remove_pending_temporaries();

// The key under which two paths name one file: absolute, normalized ("a/./b/../c"), links
// of the part that exists resolved, ASCII letters folded to lower case (on every platform:
// see file_util.cpp). Used to compare the files a run writes with each other and with the
// files it reads, before it writes any (src/app/output_plan.h, rtconvert).
std::string same_file_key(const std::string& path);

// strerror for an errno value, thread-safe.
std::string errno_text(int err);

}  // namespace rt
