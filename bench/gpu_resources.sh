#!/bin/sh
# The OpenCL kernel's resources on GPUs without one: the table of tests/gpu/budgets.txt's
# compiles (kernel x precision x target: VGPRs, AGPRs, SGPRs, scratch per lane, waves per
# SIMD, spills; PTX local frame, and ptxas's registers, stack and spills where NVIDIA's ptxas
# is installed) for the current tree, by tests/gpu/gpu_kernels.py, the gpu_compile test's
# implementation. Exit 77 where clang-16/libclc-16 are missing (tools/install-deps.sh).
#
# usage: bench/gpu_resources.sh [--build DIR] [--ceilings] [--jobs N]
#   --ceilings also prints the budget lines with ceilings from today's figures.
set -eu
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
if [ "${1:-}" = --build ]; then
  build="$2"
  shift 2
fi
[ -x "$build/raytracer" ] || { echo "gpu_resources.sh: no $build/raytracer (build it first)" >&2; exit 2; }
exec python3 "$here/tests/gpu/gpu_kernels.py" --raytracer "$build/raytracer" --ptxas "$@"
