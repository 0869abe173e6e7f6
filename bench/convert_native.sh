#!/bin/bash
# What a glTF viewer keeps of each course scene: every scene of tests/course/course_scenes.txt is
# exported to .glb and imported back twice, with rtconvert's extras (the exact round trip
# of the `convert` tests) and with --no-extras (glTF's native cameras, KHR lights and
# metallic-roughness materials only, as another tool would read the file). Both are
# rendered like the original (CPU reference, about 4096 pixels, 4 spp, seed 0) and
# compared with it: byte identity, then `compare diff` (MAE on the 0-255 scale, PSNR).
# usage: bench/convert_native.sh [BUILD_DIR]
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-build}" && pwd)"
shared="$here/../shared/scenes"
source "$here/tests/support/scene_camera.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf "| scene | with extras | --no-extras: MAE | PSNR (dB) |\n|---|---|---|---|\n"
declare -A seen
grep -v '^#' "$here/tests/course/course_scenes.txt" | while read -r name scene reference criterion flags; do
  [ -f "$shared/$scene" ] || continue
  scene_camera "$shared/$scene" $flags
  [ -n "${seen[$scene:$camera]:-}" ] && continue
  seen[$scene:$camera]=1
  rm -rf "$work"/* && mkdir -p "$work/a" "$work/b" "$work/c"
  "$build/rtconvert" "$shared/$scene" "$work/s.glb" --quiet || continue
  "$build/rtconvert" "$work/s.glb" "$work/exact.xml" --quiet
  "$build/rtconvert" "$work/s.glb" "$work/native.xml" --no-extras --width "${res[0]}" --quiet 2> /dev/null
  render() {  # SCENE DIR [--camera N]
    local s="$1" d="$2"
    shift 2
    "$build/raytracer" "$s" --device cpu --threads 1 --seed 0 --spp 4 --resolution-scale "$scale" \
      --quiet --output-dir "$d" "$@"
  }
  # shellcheck disable=SC2086
  render "$shared/$scene" "$work/a" $flags
  # shellcheck disable=SC2086
  render "$work/exact.xml" "$work/b" $flags
  # The native import names its images after the input (native.png, or native_camera<k>.png);
  # only camera $camera is rendered, so its image is the one PNG there.
  nflags=$(echo "$flags" | sed 's/--camera [0-9]*//')
  # shellcheck disable=SC2086
  render "$work/native.xml" "$work/c" --camera "$camera" $nflags
  a=$(ls "$work/a"/*.png | head -1)
  same=different
  cmp -s "$a" "$work/b/$(basename "$a")" && same=identical
  c=$(ls "$work/c"/*.png | head -1)
  metrics=$("$build/compare" diff "$a" "$c" 2>&1)
  mae=$(echo "$metrics" | grep -o 'mae [0-9.]*' | head -1 | cut -d' ' -f2)
  psnr=$(echo "$metrics" | grep -o 'psnr [0-9.inf]*' | head -1 | cut -d' ' -f2)
  printf "| %s | %s | %s | %s |\n" "$name" "$same" "${mae:-?}" "${psnr:-?}"
done
