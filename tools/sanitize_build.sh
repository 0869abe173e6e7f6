#!/bin/sh
# Configures and builds the sanitized tree: clang, AddressSanitizer + UndefinedBehaviorSanitizer,
# libFuzzer hooks; targets: the unit tests, the fuzz replay tests and every fuzzer of
# fuzz/CMakeLists.txt. Run by the test
# sanitize.build (fuzz/CMakeLists.txt); exits 77 (skipped) when clang or its sanitizer and
# libFuzzer runtimes (Debian: clang, libclang-rt-14-dev) are missing.
# usage: tools/sanitize_build.sh BUILD_DIR
set -eu
dir=$1
src=$(cd "$(dirname "$0")/.." && pwd)
if ! command -v clang++ >/dev/null 2>&1; then
  echo "skipped: clang++ is not installed (tools/install-deps.sh installs clang)"
  exit 77
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf '#include <cstddef>\n#include <cstdint>\nextern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n' \
  > "$probe/p.cpp"
if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>"$probe/err"; then
  echo "skipped: clang++ cannot link a sanitized fuzzer (install libclang-rt-14-dev):"
  head -3 "$probe/err"
  exit 77
fi
# -O1 keeps the sanitized unit tests fast enough; asserts stay on (no NDEBUG).
cmake -S "$src" -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DRT_SANITIZE=ON \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" >/dev/null
fuzzers=$(cat "$dir/fuzz/fuzzers.txt")  # Written by fuzz/CMakeLists.txt.
# shellcheck disable=SC2086  # one word per fuzzer
cmake --build "$dir" -j"$(nproc)" --target unit_tests fuzz_replay_tests $fuzzers
