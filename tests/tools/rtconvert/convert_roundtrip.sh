#!/bin/bash
# Round trip of one course scene through glTF: the scene is exported to .glb by rtconvert,
# imported back to course XML, and both are rendered with the same seed at a reduced size
# (about 4096 pixels, 4 samples per pixel, the CPU reference). Byte-identical PNGs pass at
# once; otherwise `compare exact` (the same first hits) and `compare paired` (no systematic
# per-pixel difference at alpha = 1e-4) must pass on the moment files.
#
# usage: convert_roundtrip.sh RAYTRACER RTCONVERT COMPARE SCENE.xml WORKDIR [raytracer flags...]
# Exit status: 0 pass (the last line says "identical" or "equivalent"), 1 fail, 77 skipped.
set -uo pipefail
rt="$1" conv="$2" cmp="$3" scene="$4" work="$5"
shift 5
flags=("$@")

source "$(dirname "$0")/../../support/scene_camera.sh"
skip_unless_present "$scene"
scene_camera "$scene" "${flags[@]}"

rm -rf "$work"
mkdir -p "$work/original" "$work/roundtrip"
if ! "$conv" "$scene" "$work/scene.glb" --quiet 2> "$work/export.txt"; then
  if grep -q "cannot open" "$work/export.txt"; then
    echo "SKIP: scene incomplete: $(head -1 "$work/export.txt")"
    exit 77
  fi
  cat "$work/export.txt"
  exit 1
fi
"$conv" "$work/scene.glb" "$work/roundtrip.xml" --quiet || exit 1
render() {  # SCENE DIR
  "$rt" "$1" --device cpu --threads 1 --seed 0 --spp 4 --resolution-scale "$scale" --moments \
    --quiet --output-dir "$2" "${flags[@]}"
}
render "$scene" "$work/original" || exit 1
render "$work/roundtrip.xml" "$work/roundtrip" || exit 1

status=0 identical=1
for a in "$work"/original/*.png; do
  name=$(basename "$a")
  cmp -s "$a" "$work/roundtrip/$name" && continue
  identical=0
  m="${name%.png}.moments.exr"
  "$cmp" exact "$work/original/$m" "$work/roundtrip/$m" || status=1
  "$cmp" paired "$work/original/$m" "$work/roundtrip/$m" --alpha 1e-4 || status=1
done
if [ $status -ne 0 ]; then
  echo "FAIL"
elif [ $identical -eq 1 ]; then
  echo "PASS: identical"
else
  echo "PASS: equivalent"
fi
exit $status
