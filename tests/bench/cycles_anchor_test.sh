#!/bin/bash
# bench/cycles_anchor.sh at a size that takes seconds: without Blender it stops with one
# line that says how to install it; cycles_metrics gives exact figures on equal images;
# with Blender, the diffuse Cornell box's two references agree in mean within 5 % (a wrong
# lamp power, emission side or albedo moves it far more), and the table holds every row
# with Cycles' relMSE falling with the sample count.
#
# usage: tests/bench/cycles_anchor_test.sh SOURCE_DIR BUILD_DIR SCENES_DIR WORK_DIR
# Exit status 77 (skipped) without Blender or the course's scenes.
set -euo pipefail
src="$1" build="$2" scenes="$3" work="$4"
script="$src/bench/cycles_anchor.sh"
fail() { echo "FAIL: $*" >&2; exit 1; }

# No Blender: exit 1, one line naming the package.
set +e
out=$("$script" --build "$build" --blender /nonexistent/blender 2>&1)
rc=$?
set -e
[ "$rc" = 1 ] || fail "without Blender the exit status is $rc, not 1"
[ "$(printf '%s\n' "$out" | wc -l)" = 1 ] || fail "without Blender more than one line: $out"
case "$out" in *"apt-get install --no-install-recommends blender"*) ;;
  *) fail "without Blender the line does not say how to install it: $out" ;; esac

if [ ! -f "$scenes/hw6/pathTracing/cornellbox_jaroslav_path_diffuse.xml" ]; then
  echo "skipped: the course's scenes are not in $scenes"; exit 77
fi
if ! command -v blender > /dev/null; then
  echo "skipped: Blender is not installed (apt-get install --no-install-recommends blender)"
  exit 77
fi
rm -rf "$work"
log="$work.log"
"$script" --build "$build" --work "$work" --scenes-dir "$scenes" --scenes diffuse \
  --devices cpu --modes course --scale 0.125 --spp "4 16" --reps 1 --ref-spp 256 > "$log" 2>&1 ||
  { cat "$log"; fail "bench/cycles_anchor.sh failed"; }
cat "$log"

ref="$work/ref_ours_diffuse_s0.125_256spp.exr"
[ -f "$ref" ] || fail "no cached reference $ref"
[ "$("$build/cycles_metrics" error "$ref" "$ref")" = "relmse 0 trimmed 0" ] ||
  fail "cycles_metrics error of an image against itself is not 0"
[ "$("$build/cycles_metrics" agree "$ref" "$ref" | head -1)" = "ratio 1.00000 1.00000 1.00000 1.00000" ] ||
  fail "cycles_metrics ratio of an image to itself is not 1"

ratio=$(sed -n 's/^  diffuse: mean ratio \([0-9.]*\) .*/\1/p' "$log")
[ -n "$ratio" ] || fail "no reference agreement line"
awk -v r="$ratio" 'BEGIN { exit !(r > 0.95 && r < 1.05) }' ||
  fail "Cycles' reference over ours: mean ratio $ratio, outside [0.95, 1.05]"

row() { grep "^| diffuse | $1 | $2 | $3 |" "$log" | cut -d'|' -f8 | tr -d ' '; }
for spp in 4 16; do
  for r in "- cycles" "cpu course"; do
    e=$(row ${r% *} ${r#* } $spp)
    awk -v e="$e" 'BEGIN { exit !(e > 0) }' || fail "no positive relMSE in the row $r $spp spp"
  done
done
e4=$(row - cycles 4) e16=$(row - cycles 16)
# 4 times the samples: a quarter of the error, with room for a reference of 256 spp.
awk -v a="$e4" -v b="$e16" 'BEGIN { exit !(b < 0.6 * a) }' ||
  fail "Cycles' relMSE does not fall from 4 to 16 spp: $e4, $e16"
echo "PASS: mean ratio $ratio; Cycles' relMSE $e4 at 4 spp, $e16 at 16 spp"
