#!/bin/bash
# The path tracer measured against Blender Cycles on the same scenes: the course's two
# path-traced Cornell boxes (hw6/pathTracing, camera 2: next-event estimation, importance
# sampling, no roulette) built in Cycles from their XML by bench/cycles/scene_to_blender.py.
# Renders a converged reference with each renderer (cached in the work folder), prints how
# well the two references agree, then a table per scene, device and mode of our path
# tracer at a few sample counts: CPU-seconds, relMSE against the renderer's own reference,
# efficiency and its ratio to Cycles' (docs/benchmarks.md describes the table).
#
# usage: bench/cycles_anchor.sh [--quick] [--build DIR] [--work DIR] [--blender PATH]
#          [--scenes "diffuse glass"] [--devices "cpu cl"] [--modes "course mis"]
#          [--spp "16 64 256"] [--reps N] [--ref-spp N] [--scale F] [--threads N]
#          [--extra "raytracer options"] [--scenes-dir ../shared/scenes]
# Defaults: half resolution (256 x 256), 3 repetitions, references at 4096 spp in
# BUILD/cycles_anchor; our modes: course, and mis where `raytracer --help` lists
# --path-estimator. --quick: 64 x 64, 4 and 16 spp, one repetition, references at 1024 spp.
# A full run takes about 45 minutes on 2 cores, --quick about 2. Delete the work folder to
# render the references again (after a change of either renderer).
#
# Blender is optional and used only here: apt-get install --no-install-recommends blender
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
blender=blender
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  case "${args[i]}" in
    --build) build="${args[i + 1]:-}" ;;
    --blender) blender="${args[i + 1]:-}" ;;
  esac
done
if ! command -v "$blender" > /dev/null; then
  echo "cycles_anchor: Blender not found ($blender); install it with: apt-get install --no-install-recommends blender" >&2
  exit 1
fi
for tool in raytracer cycles_metrics; do
  if [ ! -x "$build/$tool" ]; then
    echo "cycles_anchor: $build/$tool is missing; build it: cmake --build $build --target raytracer cycles_metrics" >&2
    exit 1
  fi
done
exec python3 "$here/bench/cycles/anchor.py" "$@"
