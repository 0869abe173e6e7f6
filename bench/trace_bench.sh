#!/bin/bash
# Benchmark of ray tracing speed: camera rays per CPU-second (lights removed, recursion
# depth 0, one ray per sample), BVH build time and peak memory, on tap_0200 and generated
# bumpy planes of 1 M and 4 M triangles, on both devices. Each repetition runs every device
# (and, with --baseline, a second build) once, interleaved (A B A B), so a change of the
# machine's speed between repetitions moves all of one repetition's figures together: each
# table row has its median and range, and a second table gives the ratios paired within a
# repetition (new / baseline per device; OpenCL / CPU reference per build), median and range.
#
# usage: bench/trace_bench.sh [--build DIR] [--baseline DIR] [--reps N] [--spp N]
#                             [--scenes "tap 1M 4M"] [--devices "cpu cl"] [--build-scenes "4M"]
#                             [--no-embree]
# Camera-ray rate = (spp - 1) * pixels / (CPU-s at spp - CPU-s at 1 spp): the difference
# cancels loading, BVH build, kernel compile and upload, leaving the tracing alone. The
# default 33 spp makes the traced part ~4x the fixed one (CPU-s 4.5 against 1.0 on tap_0200):
# at 9 spp the two were alike and the 1 spp run's own noise moved the rate by ~10 %.
# Where the build has embree_bench (Debian's libembree-dev installed), two more tables: the
# same camera rays traced by Embree 3 (single rays and 16-ray packets) beside ours, and the
# BVH build time of the --build-scenes against Embree's HIGH build at 1 and 2 threads.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
baseline=""
reps=5
spp=33
scene_names="tap 1M 4M"
devices="cpu cl"
build_scenes="4M"
no_embree=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$(cd "$2" && pwd)"; shift 2 ;;
    --baseline) baseline="$(cd "$2" && pwd)"; shift 2 ;;
    --reps) reps="$2"; shift 2 ;;
    --spp) spp="$2"; shift 2 ;;
    --scenes) scene_names="$2"; shift 2 ;;
    --devices) devices="$2"; shift 2 ;;
    --build-scenes) build_scenes="$2"; shift 2 ;;
    --no-embree) no_embree=1; shift ;;
    *) echo "trace_bench.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache"

# A copy of SCENE without lights and with recursion depth 0. Links to the files beside it
# and beside its folder keep relative paths such as ../ply/x.ply working.
camera_only() {  # SCENE NAME -> path of the stripped scene
  local src="$(cd "$(dirname "$1")" && pwd)" root="$work/$2"
  local dir="$root/$(basename "$src")"
  mkdir -p "$dir"
  for f in "$(dirname "$src")"/*; do [ "$f" = "$src" ] || ln -sf "$f" "$root/"; done
  for f in "$src"/*; do ln -sf "$f" "$dir/"; done
  rm -f "$dir/$(basename "$1")"
  sed -e '/<Lights>/,/<\/Lights>/d' -e 's|<MaxRecursionDepth>[0-9]*<|<MaxRecursionDepth>0<|' \
    "$1" > "$dir/$(basename "$1")"
  echo "$dir/$(basename "$1")"
}

scene_path() {  # NAME -> scene file (generating bumpy planes on demand)
  case "$1" in
    tap) echo "$here/../shared/scenes/hw3/tap_water/xml/tap_0200.xml" ;;
    *M)
      local n=$(( ${1%M} * 1000000 ))
      mkdir -p "$work/gen_$1"
      "$build/bumpy_plane" "$n" "$work/gen_$1"
      echo "$work/gen_$1/bumpy.xml" ;;
    *) echo "trace_bench.sh: unknown scene '$1'" >&2; exit 2 ;;
  esac
}

# One run: prints "cpu_seconds peak_kib bvh_ms".
measure() {  # BUILD SCENE DEVICE SPP [RAYTRACER FLAGS...]
  local log="$work/log" b="$1" scene="$2" dev="$3" n="$4"
  shift 4
  /usr/bin/time -f 'time %U %S %M' "$b/raytracer" "$scene" --device "$dev" --spp "$n" --camera 0 \
    --quiet --stats --output-dir "$work" "$@" > "$log" 2>&1 || { cat "$log" >&2; exit 1; }
  awk '/^time /{cpu = $2 + $3; mem = $4} /^stats: .*bvh/{for (i = 1; i < NF; ++i)
       if ($i == "bvh") bvh = $(i + 1)} END {print cpu, mem, bvh}' "$log"
}

# "median min max" of the numbers in $1 (space-separated).
spread() { echo $1 | tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {
  printf "%.3f %.3f %.3f\n", (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2, a[1], a[NR]}'; }
# The median of the numbers on standard input, one per line.
median() { spread "$(cat)" | cut -d' ' -f1; }
# The element-wise ratios of two equally long lists: $1[i] / $2[i].
ratios() { paste <(echo $1 | tr ' ' '\n') <(echo $2 | tr ' ' '\n') |
  awk '{printf "%s ", ($2 > 0) ? $1 / $2 : 0}'; }

builds=("$build")
[ -n "$baseline" ] && builds+=("$baseline")
echo "camera rays (no lights, depth 0), ${spp} vs 1 spp, $reps interleaved repetitions, medians"
echo "OpenCL device: $("$build/raytracer" --list-devices 2>/dev/null | head -1)"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| scene | triangles | device | build | Mrays/CPU-s | range | BVH build ms | peak MiB (1 spp) |"
echo "|---|---:|---|---|---:|---|---:|---:|"
ratio_rows=()
embree="$build/embree_bench"
[ -x "$embree" ] && [ -z "$no_embree" ] || embree=""
embree_rows=()
build_rows=()
for name in $scene_names; do
  scene="$(scene_path "$name")"
  [ -f "$scene" ] || { echo "| $name | missing | | | | | |"; continue; }
  cam="$(camera_only "$scene" "cam_$name")"
  tris=$("$build/raytracer" "$cam" --spp 1 --quiet --stats --output-dir "$work" --device cpu 2>&1 |
         grep -o '[0-9]* triangles' | head -1 | awk '{print $1}')
  pixels=$(grep -o '<ImageResolution>[0-9 ]*' "$scene" | head -1 | awk -F'>' '{split($2, r, " "); print r[1] * r[2]}')
  # The kernel caches: a kernel is built for the scene's features, and more than one sample
  # per pixel adds one, so the spp run needs its own (a tenth of the image is enough).
  for dev in $devices; do
    for b in "${builds[@]}"; do
      measure "$b" "$cam" "$dev" 1 > /dev/null
      measure "$b" "$cam" "$dev" "$spp" --resolution-scale 0.1 > /dev/null
    done
  done
  declare -A rate=() bvh=() mem=()
  for ((i = 0; i < reps; i++)); do
    for dev in $devices; do
      for b in "${builds[@]}"; do
        read -r c1 m1 b1 < <(measure "$b" "$cam" "$dev" 1)
        read -r cn mn bn < <(measure "$b" "$cam" "$dev" "$spp")
        rate["$dev $b"]+="$(awk -v a="$c1" -v b="$cn" -v r="$(( (spp - 1) * pixels ))" \
                           'BEGIN {print (b > a) ? r / (b - a) * 1e-6 : 0}') "
        bvh["$dev $b"]+="$b1 "
        mem["$dev $b"]+="$m1 "
      done
    done
  done
  for dev in $devices; do
    for b in "${builds[@]}"; do
      label=$([ "$b" = "$build" ] && echo new || echo baseline)
      read -r r lo hi < <(spread "${rate["$dev $b"]}")
      [ "$b" = "$build" ] && [ "$dev" = cpu ] && renderer_rate="$r"
      printf '| %s | %s | %s | %s | %.2f | %.2f-%.2f | %.0f | %.0f |\n' "$name" "$tris" "$dev" \
        "$label" "$r" "$lo" "$hi" "$(echo ${bvh["$dev $b"]} | tr ' ' '\n' | median)" \
        "$(echo ${mem["$dev $b"]} | tr ' ' '\n' | median | awk '{print $1 / 1024}')"
    done
    if [ -n "$baseline" ]; then
      read -r r lo hi < <(spread "$(ratios "${rate["$dev $build"]}" "${rate["$dev $baseline"]}")")
      ratio_rows+=("$(printf '| %s | %s: new / baseline | %.2f | %.2f-%.2f |' "$name" "$dev" "$r" "$lo" "$hi")")
    fi
  done
  if [[ " $devices " == *" cpu "* && " $devices " == *" cl "* ]]; then
    for b in "${builds[@]}"; do
      label=$([ "$b" = "$build" ] && echo new || echo baseline)
      read -r r lo hi < <(spread "$(ratios "${rate["cl $b"]}" "${rate["cpu $b"]}")")
      ratio_rows+=("$(printf '| %s | %s: OpenCL / CPU reference | %.2f | %.2f-%.2f |' "$name" "$label" "$r" "$lo" "$hi")")
    done
  fi
  unset rate bvh mem
  if [ -n "$embree" ]; then
    # The renderer again on one thread, as Embree's figures are taken: two threads on this
    # kind of VM share a core's resources, which lowers the rate per CPU-second of each.
    rates1=""
    for ((i = 0; i < reps; i++)); do
      read -r c1 _ _ < <(measure "$build" "$cam" cpu 1 --threads 1)
      read -r cn _ _ < <(measure "$build" "$cam" cpu "$spp" --threads 1)
      rates1+="$(awk -v a="$c1" -v b="$cn" -v r="$(( (spp - 1) * pixels ))" \
                 'BEGIN {print (b > a) ? r / (b - a) * 1e-6 : 0}') "
    done
    renderer_rate1="$(echo $rates1 | tr ' ' '\n' | median)"
    # The same camera rays, one thread: ours (the reference's traversal alone) and Embree's.
    line="$("$embree" "$cam" --spp "$spp" --reps "$reps")" || { echo "$line" >&2; exit 1; }
    embree_rows+=("$(echo "$line" | awk -v n="$name" -v r="${renderer_rate:-0}" -v r1="$renderer_rate1" '{
      for (i = 1; i < NF; i += 2) v[$i] = $(i + 1)
      printf "| %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s %% / %s %% |", n,
        v["triangles"], v["rays"], r, r1, v["ours"], v["embree1"], v["embree16"], r / v["embree1"],
        r1 / v["embree1"], v["ratio1"], v["agree1"], v["agree16"]}')")
    if [[ " $build_scenes " == *" $name "* ]]; then
      out="$("$embree" "$cam" --build --reps "$reps")" || { echo "$out" >&2; exit 1; }
      same=$(echo "$out" | awk '/^same_tree/{print $2}')
      while read -r _ threads _ ow oc _ ew ec; do
        build_rows+=("| $name | $tris | $threads | $ow | $oc | $ew | $ec | $same |")
      done < <(echo "$out" | grep '^build ')
    fi
    unset renderer_rate
  fi
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ ${#ratio_rows[@]} -gt 0 ]; then
  echo
  echo "Ratios of the camera-ray rates, paired within each repetition: median and range."
  echo
  echo "| scene | ratio | median | range |"
  echo "|---|---|---:|---|"
  printf '%s\n' "${ratio_rows[@]}"
fi
if [ -n "$embree" ]; then
  echo
  echo "The same camera rays traced by Embree 3 (BVH quality HIGH, no culling), Mrays per"
  echo "CPU-second of one thread; \"renderer\" is the CPU reference's rate above (a whole"
  echo "sample: camera ray, traversal, surface, film; all threads), \"renderer, 1 thread\" the"
  echo "same with --threads 1, timed as Embree is; \"traversal alone\" our cl/bvh/bvh.h called"
  echo "on the rays as Embree is; agreement: share of rays with the same hit distance (rel. 1e-4)"
  echo "ours vs Embree single, Embree single vs packets."
  echo
  echo "| scene | triangles | rays | ours, renderer | ours, renderer, 1 thread | ours, traversal alone | Embree single rays | Embree 16-ray packets | renderer / Embree single | renderer 1 thread / Embree single | traversal / Embree single | agreement |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  printf '%s\n' "${embree_rows[@]}"
  if [ ${#build_rows[@]} -gt 0 ]; then
    echo
    echo "BVH build, medians of $reps: ours is all of prepare_scene (what the renderer waits"
    echo "for), Embree's is rtcCommitScene at quality HIGH; same tree: ours at 1 and 2 threads."
    echo
    echo "| scene | triangles | threads | ours wall s | ours CPU s | Embree HIGH wall s | Embree CPU s | same tree |"
    echo "|---|---:|---:|---:|---:|---:|---:|---|"
    printf '%s\n' "${build_rows[@]}"
  fi
else
  echo
  [ -n "$no_embree" ] ||
    echo "(no Embree columns: build/embree_bench is built only where libembree-dev is installed)"
fi
