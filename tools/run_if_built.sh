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
# LeakSanitizer's own stop-the-world tracer sometimes crashes at exit on a loaded machine,
# after every test passed ("Tracer caught signal 11", then "LeakSanitizer has encountered a
# fatal error"; google/sanitizers#1353, where rerunning is the known remedy): that exact
# signature, and only it, earns one more run. A leak report ("detected memory leaks") or any
# other failure fails at once.
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
status=0
"$@" > "$log" 2>&1 || status=$?
cat "$log"
if [ "$status" -ne 0 ] && grep -q "^Tracer caught signal" "$log" &&
  grep -q "LeakSanitizer has encountered a fatal error" "$log" &&
  ! grep -q "detected memory leaks" "$log"; then
  echo "run_if_built.sh: LeakSanitizer's tracer crashed at exit (not a finding); running once more"
  "$@"
  exit $?
fi
exit "$status"
