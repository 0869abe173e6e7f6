#!/bin/bash
# Full renders of the course's hw3 scenes at their own sample counts, this build against a
# baseline build, on both devices, in CPU-seconds (user + system of the whole process:
# loading, BVH build, kernel compile and rendering), medians of interleaved runs (A B A B).
# The machine this was written on is shared, so CPU-seconds, not wall time. "sampling" is
# the CPU-seconds at the scene's sample count minus those at 1 spp: the per-sample work
# alone, without the fixed costs (loading, BVH build, PoCL's start), which weigh more at a
# reduced resolution than at full size. Scenes whose files are missing are listed so.
#
# usage: bench/hw3_bench.sh --baseline DIR [--build DIR] [--reps N] [--scale F]
#                           [--devices "cpu cl"] [SCENE.xml ...]
# --scale renders every camera at F times its resolution (the per-pixel work is the same;
# the default 0.25 keeps the whole run in minutes); the sample counts are the scenes' own.
# Each pair of images is compared: "same" when the two builds wrote identical bytes.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
baseline=""
reps=2
scale=0.25
devices="cpu cl"
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$(cd "$2" && pwd)"; shift 2 ;;
    --baseline) baseline="$(cd "$2" && pwd)"; shift 2 ;;
    --reps) reps="$2"; shift 2 ;;
    --scale) scale="$2"; shift 2 ;;
    --devices) devices="$2"; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ -n "$baseline" ] || { echo "hw3_bench.sh: --baseline DIR is required" >&2; exit 2; }
shared="$here/../shared/scenes/hw3"
if [ ${#scenes[@]} -eq 0 ]; then
  for s in cornellbox_area cornellbox_boxes_dynamic cornellbox_brushed_metal dragon_dynamic \
           focusing_dragons metal_glass_plates spheres_dof; do scenes+=("$shared/$s.xml"); done
  scenes+=("$shared/tap_water/xml/tap_0200.xml")
fi
work="$(mktemp -d)"
mkdir -p "$work/warm"
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache"

median() { sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

cpu_seconds() {  # BUILD SCENE DEVICE OUT_DIR FLAGS... -> CPU-seconds of one render
  local b="$1" scene="$2" dev="$3" out="$4"
  shift 4
  mkdir -p "$out"
  /usr/bin/time -f 'time %U %S' "$b/raytracer" "$scene" --device "$dev" --quiet \
    --resolution-scale "$scale" --output-dir "$out" "$@" 2> "$work/err" ||
    { cat "$work/err" >&2; exit 1; }
  awk '/^time /{print $2 + $3}' "$work/err"
}

echo "hw3 at own sample counts, resolution x$scale, $reps interleaved repetitions (A B A B),"
echo "CPU-seconds of the whole process, medians; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| scene | spp | device | baseline CPU-s | this build CPU-s | speed-up | baseline sampling CPU-s | this build sampling CPU-s | sampling speed-up | images |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---|"
for scene in "${scenes[@]}"; do
  [ -f "$scene" ] || { echo "| $(basename "$scene") | missing | | | | | |"; continue; }
  flags=()
  case "$scene" in *cornellbox_boxes_dynamic*) flags=(--cull-back-faces) ;; esac
  spp=$(grep -o '<NumSamples>[0-9]*' "$scene" | head -1 | grep -o '[0-9]*$')
  for dev in $devices; do
    # Kernel caches filled first, so no run pays a cold compile. Both sample counts warm
    # them: one sample per pixel and many compile different kernel variants (the features
    # word differs: --stats shows "features").
    missing=""
    for b in "$baseline" "$build"; do
      for warm_spp in 1 "$spp"; do
        "$b/raytracer" "$scene" --device "$dev" --quiet --spp "$warm_spp" --resolution-scale 0.05 \
          --output-dir "$work/warm" "${flags[@]}" > /dev/null 2> "$work/err" ||
          missing="$(head -c 160 "$work/err" | head -1)"
      done
    done
    if [ -n "$missing" ]; then
      echo "| $(basename "$scene" .xml) | $spp | $dev | skipped: $missing | | | | | | |"
      continue
    fi
    a=() n=() a1=() n1=()
    for ((i = 0; i < reps; i++)); do
      a+=("$(cpu_seconds "$baseline" "$scene" "$dev" "$work/a" "${flags[@]}")")
      n+=("$(cpu_seconds "$build" "$scene" "$dev" "$work/n" "${flags[@]}")")
      a1+=("$(cpu_seconds "$baseline" "$scene" "$dev" "$work/a1" "${flags[@]}" --spp 1)")
      n1+=("$(cpu_seconds "$build" "$scene" "$dev" "$work/n1" "${flags[@]}" --spp 1)")
    done
    ma=$(printf '%s\n' "${a[@]}" | median)
    mn=$(printf '%s\n' "${n[@]}" | median)
    sa=$(awk -v t="$ma" -v o="$(printf '%s\n' "${a1[@]}" | median)" 'BEGIN {print t - o}')
    sn=$(awk -v t="$mn" -v o="$(printf '%s\n' "${n1[@]}" | median)" 'BEGIN {print t - o}')
    same=$(diff -rq "$work/a" "$work/n" > /dev/null && echo same || echo differ)
    printf '| %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s |\n' \
      "$(basename "$scene" .xml)" "$spp" "$dev" "$ma" "$mn" \
      "$(awk -v a="$ma" -v b="$mn" 'BEGIN {print a / b}')" "$sa" "$sn" \
      "$(awk -v a="$sa" -v b="$sn" 'BEGIN {print (b > 0) ? a / b : 0}')" "$same"
    rm -rf "${work:?}/a" "${work:?}/n" "${work:?}/a1" "${work:?}/n1"
  done
done
