#!/bin/bash
# One pass over what a machine with an OpenCL GPU can tell that this one cannot, in under
# 8 minutes there (docs/gpu.md): the OpenCL devices, the suite's CL-vs-CPU comparison
# (tests/course/cl_vs_cpu.sh quick: `compare exact` and `paired` at equal seeds, `welch` at
# different ones) on a subset of the course scenes, camera rays per second on hw3 tap_0200,
# and the render times of the hw3 course scenes and of one hw6 path-traced camera; then one
# table, whose last column says which figures mean something only on a GPU.
#
# usage: bench/gpu_check.sh [--build DIR] [--dry-run] [--cl-device SEL]
# --dry-run (automatic when --list-devices shows no GPU, e.g. PoCL here): every step at tiny
# resolutions and with the all-features kernel (--kernel generic: one kernel compile for the
# whole run instead of one per scene), to check the script end to end in under 3 minutes.
# The kernels are cached as the raytracer caches them ($XDG_CACHE_HOME or ~/.cache), so a
# second run skips the compiles; the table gives each render's compile time.
# Exit status: 0 when every step ran and every comparison passed, 1 otherwise.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
dry=""
device=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$(cd "$2" && pwd)" || exit 2; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --cl-device) device=(--cl-device "$2"); shift 2 ;;
    *) echo "gpu_check.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
rt="$build/raytracer"
cmp="$build/compare"
scenes="$here/../shared/scenes"
for b in "$rt" "$cmp"; do
  [ -x "$b" ] || { echo "gpu_check.sh: no $b (build raytracer and compare first)" >&2; exit 2; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
start=$(date +%s)
rows=()
status=0
row() { rows+=("| $1 | $2 | $3 |"); }  # FIGURE VALUE GPU-ONLY

echo "== OpenCL devices (raytracer --list-devices)"
if ! "$rt" --list-devices > "$work/devices" 2>&1; then
  cat "$work/devices"
  echo "gpu_check.sh: no OpenCL device at all" >&2
  exit 1
fi
cat "$work/devices"
if ! grep -q ", GPU," "$work/devices" && [ -z "$dry" ]; then
  echo "(no GPU listed: dry run)"
  dry=1
fi
row "OpenCL devices" "$(grep -c . "$work/devices"), the first: $(head -1 "$work/devices" | cut -d'(' -f1)" no
# Dry run: tiny images, one kernel for all. On a GPU: the scenes' own sizes.
small=()
[ -n "$dry" ] && small=(--kernel generic)
cl=(--device cl "${device[@]}" "${small[@]}")

# One CL render with --stats; prints "render_s compile_ms mrays" (render_s: the render phase's
# wall clock, which leaves out loading, BVH build, kernel compile and upload).
render_cl() {  # SCENE OUTDIR [raytracer flags...]
  local scene="$1" out="$2"
  shift 2
  mkdir -p "$out"
  if ! "$rt" "$scene" "${cl[@]}" --stats --quiet --output-dir "$out" "$@" > "$out/log" 2>&1; then
    cat "$out/log" >&2
    return 1
  fi
  awk '/^stats: /{for (i = 1; i < NF; ++i) {if ($i == "render") r += $(i + 1)
       if ($i == "compile") c += $(i + 1); if ($i == "|" && $(i + 2) == "Mrays/s") m = $(i + 1)}}
       END {printf "%.3f %.0f %.3f\n", r, c, m}' "$out/log"
}

# The course scene line NAME of tests/course/course_scenes.txt: "SCENE flags...".
course_line() { awk -v n="$1" '$1 == n {$1 = ""; $3 = ""; $4 = ""; print}' "$here/tests/course/course_scenes.txt"; }

echo "== CL vs CPU reference (tests/course/cl_vs_cpu.sh quick)"
for name in hw1.bunny hw1.cornellbox_recursive hw3.metal_glass_plates hw4.wood_box_all; do
  read -r scene flags <<< "$(course_line "$name")"
  # shellcheck disable=SC2086
  "$here/tests/course/cl_vs_cpu.sh" "$rt" "$cmp" "$scenes/$scene" "$work/cvc_$name" quick $flags \
    "${device[@]}" "${small[@]}" > "$work/cvc_$name.log" 2>&1
  rc=$?
  case $rc in
    0) verdict=PASS ;;
    77) verdict=SKIP ;;
    *) verdict=FAIL ;;
  esac
  [ "$verdict" = FAIL ] && { status=1; tail -20 "$work/cvc_$name.log"; }
  echo "$name: $verdict"
  row "CL vs CPU $name (exact, paired, welch)" "$verdict" no
done

echo "== camera rays per second, hw3 tap_0200 (no lights, depth 0, as bench/trace_bench.sh)"
# A copy of the scene without lights and with recursion depth 0, beside links to its
# neighbours, so that its relative ../ply paths still resolve: each sample is a camera ray.
tap="$scenes/hw3/tap_water/xml/tap_0200.xml"
mkdir -p "$work/tap/xml"
ln -s "$scenes/hw3/tap_water/ply" "$work/tap/ply"
sed -e '/<Lights>/,/<\/Lights>/d' -e 's|<MaxRecursionDepth>[0-9]*<|<MaxRecursionDepth>0<|' \
  "$tap" > "$work/tap/xml/tap_0200.xml"
pixels=$(grep -o '<ImageResolution>[0-9 ]*' "$tap" | head -1 | awk -F'>' '{split($2, r, " "); print r[1] * r[2]}')
spp=33 scale=1
[ -n "$dry" ] && spp=17 scale=0.1
pixels=$(awk -v p="$pixels" -v s="$scale" 'BEGIN {print int(p * s * s)}')
# The rate from the difference of two sample counts cancels what a render does once per launch.
if read -r t1 _ < <(render_cl "$work/tap/xml/tap_0200.xml" "$work/tap1" --spp 1 --resolution-scale "$scale") &&
   read -r tn cn _ < <(render_cl "$work/tap/xml/tap_0200.xml" "$work/tapn" --spp "$spp" --resolution-scale "$scale"); then
  rate=$(awk -v a="$t1" -v b="$tn" -v r="$(( (spp - 1) * pixels ))" 'BEGIN {
    if (b > a) printf "%.1f", r / (b - a) * 1e-6; else print "n/a (too fast to time)"}')
  echo "tap_0200: $rate Mrays/s ($spp vs 1 spp, $pixels pixels; render $t1 s / $tn s, compile $cn ms)"
  row "camera rays, tap_0200, Mrays/s (wall clock; kernel compile ms)" "$rate ($cn)" yes
else
  status=1
  row "camera rays, tap_0200" "FAIL" yes
fi

echo "== render times (CL device)"
hw3=$(awk '$1 ~ /^hw3\./ {print $1}' "$here/tests/course/course_scenes.txt")
for name in $hw3 hw6.path_glass; do
  if [ "$name" = hw6.path_glass ]; then
    scene="hw6/pathTracing/cornellbox_jaroslav_path_glass.xml" flags="--camera 0"
  else
    read -r scene flags <<< "$(course_line "$name")"
  fi
  size=()
  [ -n "$dry" ] && size=(--resolution-scale 0.05)
  [ -f "$scenes/$scene" ] || { row "render $name" "missing scene" yes; continue; }
  # shellcheck disable=SC2086
  if read -r t c m < <(render_cl "$scenes/$scene" "$work/r_$name" $flags "${size[@]}"); then
    echo "$name: render $t s, compile $c ms, $m Mrays/s"
    row "render $name: s (kernel compile ms, Mrays/s)" "$t ($c, $m)" yes
  else
    status=1
    row "render $name" FAIL yes
  fi
done

elapsed=$(( $(date +%s) - start ))
echo
echo "gpu_check.sh: $([ -n "$dry" ] && echo "DRY RUN (no GPU: figures marked yes are not GPU figures)" ||
  echo "GPU run"), $elapsed s, $(date -u +%Y-%m-%dT%H:%MZ)"
echo
echo "| figure | value | needs a GPU to mean anything |"
echo "|---|---|---|"
printf '%s\n' "${rows[@]}"
exit $status
