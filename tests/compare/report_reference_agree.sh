#!/bin/bash
# `compare reference` on fresh renders of course scenes, at the suite's settings (full
# resolution, the scene's own sample count, the flags of tests/course/course_scenes.txt):
#   report_reference_agree.sh RAYTRACER COMPARE SOURCE_DIR SCENES_DIR WORK_DIR NAME...
# Each NAME's render must pass, as the reference tests require of it (their verdict on the
# same scenes: ctest -L reference_full, configured with -DRT_FULL_REFERENCE=ON). Prints one
# line per scene and writes WORK_DIR/NAME/report.html; exit 0 when every render passes, 1
# otherwise, 77 when none of the scenes' files is present.
set -u
raytracer=$1 compare=$2 source=$3 scenes=$4 work=$5
shift 5
list=$source/tests/course/course_scenes.txt
status=0 checked=0
for name in "$@"; do
  line=$(grep -E "^$name[[:space:]]" "$list") || { echo "$name: not in $list"; exit 1; }
  read -r _ scene reference _ flags <<<"$line"
  if [ ! -f "$scenes/$scene" ] || [ ! -f "$scenes/$reference" ]; then
    echo "$name: SKIP ($scenes/$scene or its reference is not present)"
    continue
  fi
  out=$work/$name
  rm -rf "$out" && mkdir -p "$out"
  # shellcheck disable=SC2086  # the flags are words of course_scenes.txt
  if ! "$raytracer" "$scenes/$scene" $flags --device cpu --output-dir "$out" >"$out/render.log" 2>&1; then
    echo "$name: render failed: $(tail -1 "$out/render.log")"
    status=1
    continue
  fi
  png=$out/$(basename "$reference")
  [ -f "$png" ] || png=$(find "$out" -name '*.png' | head -1)
  checked=$((checked + 1))
  "$compare" reference "$png" "$scenes/$reference" >"$out/check.log" 2>&1
  rc=$?
  "$compare" report "$png" "$scenes/$reference" --out "$out/report.html" >/dev/null 2>&1
  echo "$name: $(tail -1 "$out/check.log") (exit $rc)"
  [ $rc -eq 0 ] || status=1
done
[ $checked -gt 0 ] || { echo "SKIP: none of the scenes is present"; exit 77; }
exit $status
