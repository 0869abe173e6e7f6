#!/bin/bash
# Kernel-vs-reference validation of one scene: renders it with the OpenCL kernel and with
# the CPU reference, with moment files, and requires `compare welch` per pixel and per 8x8
# tile (different seeds: equal expected images), `compare exact` and `compare paired`
# (equal seeds: the same first hits, no systematic per-pixel difference) to pass.
# Each statistical verdict runs at alpha = 1e-4, so that the whole suite (about 40 scenes,
# 3 statistical verdicts each) falsely fails two correct devices with probability at most
# about 1 %.
#
# usage: cl_vs_cpu.sh RAYTRACER COMPARE SCENE.xml WORKDIR quick|full [raytracer flags...]
# quick: about 4096 pixels of the same view (--resolution-scale) at 24 samples per pixel
#        (not a perfect square, so samples are independent and Welch's test runs at its
#        nominal level).
# full:  the scene's own resolution and sample count (at least 15 spp: Welch needs a
#        variance); perfect-square counts are stratified, which makes welch conservative.
# Exit status: 0 pass, 1 fail, 77 skipped (no OpenCL device, or the scene's files are
# missing).
set -uo pipefail
rt="$1" cmp="$2" scene="$3" work="$4" mode="$5"
shift 5
flags=("$@")
# RT_TEST_PRECISION=double reruns the suite in double (README: precision).
[ "${RT_TEST_PRECISION:-}" = double ] && flags+=(--precision double)

source "$(dirname "$0")/../support/scene_camera.sh"
skip_unless_present "$scene"
if ! "$rt" --list-devices > /dev/null 2>&1; then
  echo "SKIP: no OpenCL device"
  exit 77
fi

# The camera this test renders: its resolution and sample count decide the reduced size.
scene_camera "$scene" "${flags[@]}"
if [ "$mode" = quick ]; then
  size=(--resolution-scale "$scale" --spp 24)
else
  size=()
  [ "$spp" -lt 2 ] && size=(--spp 15)
fi

rm -rf "$work"
mkdir -p "$work/cpu0" "$work/cl0" "$work/cl1"
render() {  # DEVICE SEED DIR
  "$rt" "$scene" --device "$1" --seed "$2" --output-dir "$3" --moments --quiet \
    "${size[@]}" "${flags[@]}" 2> "$3/stderr.txt"
}
if ! render cpu 0 "$work/cpu0"; then
  if grep -q "cannot open" "$work/cpu0/stderr.txt"; then
    echo "SKIP: scene incomplete: $(head -1 "$work/cpu0/stderr.txt")"
    exit 77
  fi
  cat "$work/cpu0/stderr.txt"
  exit 1
fi
for run in "cl 0 $work/cl0" "cl 1 $work/cl1"; do
  # shellcheck disable=SC2086
  if ! render $run; then
    cat "${run##* }/stderr.txt"
    exit 1
  fi
done

status=0
for a in "$work"/cpu0/*.moments.exr; do
  name=$(basename "$a")
  maps="$work/maps/${name%.moments.exr}"
  mkdir -p "$maps"
  echo "== $(basename "$scene") ${flags[*]} ${size[*]}: $name"
  "$cmp" welch "$a" "$work/cl1/$name" --alpha 1e-4 --out-dir "$maps" || status=1
  "$cmp" welch "$a" "$work/cl1/$name" --alpha 1e-4 --tile 8 --out-dir "$maps/tile8" || status=1
  "$cmp" exact "$a" "$work/cl0/$name" --out-dir "$maps" || status=1
  "$cmp" paired "$a" "$work/cl0/$name" --alpha 1e-4 --out-dir "$maps" || status=1
done
[ $status -eq 0 ] && echo "PASS" || echo "FAIL"
exit $status
