#!/bin/bash
# Benchmark: renders each scene on every configuration, side by side in one run, and
# prints a table of medians. Each render is validated against the course's reference
# image (4x4-downsampled mean absolute error) or, without one, against the CPU render.
#
# usage: bench/render_bench.sh [--spp N] [--reps N] [--build DIR] [SCENE.xml ...]
# Defaults: 16 samples per pixel, 3 repetitions, the hw3 scenes and tap_0200.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
spp=16
reps=3
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --spp) spp="$2"; shift 2 ;;
    --reps) reps="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
shared="$here/../shared/scenes"
if [ ${#scenes[@]} -eq 0 ]; then
  for s in cornellbox_area cornellbox_boxes_dynamic cornellbox_brushed_metal metal_glass_plates \
           spheres_dof; do scenes+=("$shared/hw3/$s.xml"); done
  scenes+=("$shared/hw3/tap_water/xml/tap_0200.xml")
fi
rt="$build/raytracer"
cmp="$build/compare"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export XDG_CACHE_HOME="$out/cache"

median() { sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
field() { grep -o "$1 [0-9.]*" | head -1 | awk '{print $NF}'; }

# One configuration: prints "seconds Msamples/s Mrays/s" medians and keeps the last PNG.
run() {
  local name="$1" scene="$2"; shift 2
  # The course's image of this scene was made with camera rays culling back faces.
  case "$scene" in *cornellbox_boxes_dynamic*) set -- "$@" --cull-back-faces ;; esac
  local t=() s=() r=()
  for ((i = 0; i < reps; i++)); do
    local line
    line=$("$rt" "$scene" --spp "$spp" --camera 0 --quiet --stats --output-dir "$out/$name" "$@" 2>&1 \
           | grep '^stats: .*render')
    t+=("$(echo "$line" | field 'render')")
    s+=("$(echo "$line" | grep -o '[0-9.]* Msamples/s' | awk '{print $1}')")
    r+=("$(echo "$line" | grep -o '[0-9.]* Mrays/s' | awk '{print $1}')")
  done
  echo "$(printf '%s\n' "${t[@]}" | median) $(printf '%s\n' "${s[@]}" | median) $(printf '%s\n' "${r[@]}" | median)"
}

compile_ms() {  # compile time of the first camera, cold (empty caches) or cached
  "$rt" "$1" --spp 1 --camera 0 --quiet --stats --output-dir "$out/c" --device cl "${@:2}" 2>&1 \
    | grep -o 'kernel compile [0-9.]*' | awk '{print $NF}'
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
echo "spp $spp, $reps repetitions, medians; OpenCL device: $("$rt" --list-devices 2>/dev/null | head -1)"
echo
echo "| scene | config | time s | Msamples/s | Mrays/s | ratio | validation |"
echo "|---|---|---:|---:|---:|---|---|"
for scene in "${scenes[@]}"; do
  [ -f "$scene" ] || { echo "| $(basename "$scene") | missing | | | | | |"; continue; }
  base=$(basename "$scene" .xml)
  rm -rf "${out:?}"/{cpu2,cpu1,cls,clg,c}
  mkdir -p "$out"/{cpu2,cpu1,cls,clg,c}
  read -r t2 s2 r2 < <(run cpu2 "$scene" --device cpu --threads 2)
  read -r t1 s1 r1 < <(run cpu1 "$scene" --device cpu --threads 1)
  read -r ts ss rs < <(run cls "$scene" --device cl)
  read -r tg sg rg < <(run clg "$scene" --device cl --kernel generic)
  rm -rf "$out/cache"
  cold=$(POCL_KERNEL_CACHE=0 compile_ms "$scene" --no-kernel-cache)
  compile_ms "$scene" >/dev/null
  cached=$(compile_ms "$scene")
  png=$(ls "$out/cpu2" | head -1)
  ref=$(find "$(dirname "$scene")" "$(dirname "$scene")/.." -path '*reference*' -name "$png" 2>/dev/null | head -1)
  validate() {
    if [ -n "$ref" ]; then
      "$cmp" diff "$ref" "$out/$1/$png" | grep -o '4x4: mae [0-9.]*' | awk '{print "reference 4x4 MAE " $NF}'
    else
      "$cmp" diff "$out/cpu2/$png" "$out/$1/$png" | awk '{print "MAE vs cpu-2 " $2}'
    fi
  }
  echo "| $base | cpu 2 threads | $t2 | $s2 | $r2 | $(ratio "$t1" "$t2")x vs 1 thread | $(validate cpu2) |"
  echo "| | cpu 1 thread | $t1 | $s1 | $r1 | | $(validate cpu1) |"
  echo "| | cl specialized | $ts | $ss | $rs | cpu-2/cl $(ratio "$t2" "$ts") | $(validate cls) |"
  echo "| | cl generic | $tg | $sg | $rg | generic/specialized $(ratio "$tg" "$ts") | $(validate clg) |"
  echo "| | kernel compile | cold ${cold} ms, cached ${cached} ms | | | | |"
done
