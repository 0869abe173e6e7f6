#!/bin/bash
# Regenerates the figures and per-pixel CSVs of docs/course_pixel_residue.md: for each
# course image named (default: the two below 99.9 %), a rounding-sized ensemble of our
# renderer (tools/explain_ensemble.py, full size, --device cpu) and the explanation of
# every pixel where our image differs from the course's (tools/explain_pixels.py).
#
# usage: tools/course_pixel_residue.sh [NAME ...]     NAME: a line of tests/course/course_scenes.txt
#   RT_BUILD (default build), RT_WORK (default /tmp/course_pixel_residue) and RT_CSV_DIR
#   (default docs/course_pixel_residue) may be set. About 1 CPU-minute per hw1 image and 10
#   per hw2 grass_desert.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${RT_BUILD:-$here/build}"
work="${RT_WORK:-/tmp/course_pixel_residue}"
csv_dir="${RT_CSV_DIR:-$here/docs/course_pixel_residue}"
scenes="$here/../shared/scenes"
[ $# -gt 0 ] || set -- hw1.spheres hw1.spheres_mirror
mkdir -p "$csv_dir"
for name in "$@"; do
  line="$(awk -v n="$name" '$1 == n' "$here/tests/course/course_scenes.txt")"
  [ -n "$line" ] || { echo "$name: not a line of tests/course/course_scenes.txt" >&2; exit 2; }
  read -r _ scene reference _ flags <<< "$line"
  echo "## $name"
  echo
  rm -rf "$work/$name"
  # shellcheck disable=SC2086  # The flags are words.
  python3 "$here/tools/explain_ensemble.py" "$scenes/$scene" "$work/$name" \
    --raytracer "$build/raytracer" -- $flags 2> /dev/null
  # On hw1 scenes the independent double-precision tracer evaluates each differing pixel
  # with the course's textbook sphere test in float (its hit point o + t d off the sphere by
  # the float root's error, its normal (p - c) / r not of unit length): a member of its own.
  model=()
  if [[ $name == hw1.* ]]; then
    base="$(awk -F '\t' '$1 == "base" { print $4 }' "$work/$name/members.tsv")"
    python3 "$here/tools/classify_pixels.py" "$work/$name/$base" \
      "$scenes/$reference" --list > "$work/$name/differing.txt"
    # shellcheck disable=SC2086
    if python3 "$here/tools/whitted_probe.py" "$scenes/$scene" 0 0 $flags --set sphere=f32_abc \
      --batch "$work/$name/differing.txt" > "$work/$name/model_f32_sphere.txt"; then
      model=(--model "f32_sphere=$work/$name/model_f32_sphere.txt")
    fi
  fi
  python3 "$here/tools/explain_pixels.py" "$work/$name" "$scenes/$reference" --markdown \
    --list-unexplained --csv "$csv_dir/$name.csv" "${model[@]}"
  echo
done
