#!/bin/sh
# Runs a program of the sanitized tree, or exits 77 (skipped) when that tree was not built
# (sanitize.build says why). Sanitizer reports fail the run.
# usage: tools/run_if_built.sh PROGRAM [ARGS...]
set -eu
if [ ! -x "$1" ]; then
  echo "skipped: $1 was not built (see the output of the test sanitize.build)"
  exit 77
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
# PoCL and LLVM leak by design when they compile a kernel (see tools/lsan.supp).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(cd "$(dirname "$0")" && pwd)/lsan.supp}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
exec "$@"
