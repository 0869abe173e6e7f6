#!/bin/bash
# The cost of --precision double: for each scene and device, renders float and double
# interleaved (F D F D ...) and prints the median CPU-seconds (user + system, which a
# loaded machine disturbs less than wall time) of each and their ratio. The kernel cache
# is warmed first, so compile time is not counted.
#
# usage: bench/precision_bench.sh [RUNS] [raytracer flags...]   (default 3 runs each;
#        the speed-accuracy sweep's scenes at quarter resolution and 16 spp)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
rt="$here/build/raytracer"
shared="$here/../shared/scenes"
runs="${1:-3}"
shift || true
extra=("$@")
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scenes=(hw3/cornellbox_area.xml hw3/metal_glass_plates.xml hw3/spheres_dof.xml
        hw3/tap_water/xml/tap_0200.xml)
cpu_seconds() {  # DEVICE PRECISION SCENE
  /usr/bin/time -f "%U %S" -o "$out/time" "$rt" "$shared/$3" --device "$1" --precision "$2" \
    --resolution-scale 0.25 --spp 16 --output-dir "$out" --quiet "${extra[@]}" > /dev/null
  awk '{ printf "%.3f\n", $1 + $2 }' "$out/time"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "| scene | device | float CPU-s | double CPU-s | double / float |"
echo "|---|---|---:|---:|---:|"
for scene in "${scenes[@]}"; do
  [ -f "$shared/$scene" ] || { echo "| $scene | missing | | | |"; continue; }
  for dev in cpu cl; do
    cpu_seconds "$dev" float "$scene" > /dev/null
    cpu_seconds "$dev" double "$scene" > /dev/null
    : > "$out/f"
    : > "$out/d"
    for _ in $(seq "$runs"); do
      cpu_seconds "$dev" float "$scene" >> "$out/f"
      cpu_seconds "$dev" double "$scene" >> "$out/d"
    done
    f="$(median < "$out/f")" d="$(median < "$out/d")"
    awk -v s="$(basename "$scene" .xml)" -v dev="$dev" -v f="$f" -v d="$d" \
      'BEGIN { printf "| %s | %s | %.2f | %.2f | %.2f |\n", s, dev, f, d, d / f }'
  done
done
