#!/bin/bash
# Distributed rendering benchmark (src/distributed/): the seven tap-water frames of
# ../shared/scenes/hw3/tap_water/xml and one large image (tap_0000 alone), rendered by
#   1x2  one process, 2 CPU threads (no mpirun): the single-process baseline
#   np1  mpirun, 1 rank (its threads: the node's cores)
#   np2  mpirun, 2 ranks x 1 thread
#   np4  mpirun, 4 ranks x 1 thread (oversubscribed on 2 cores)
# on the CPU reference, interleaved (1x2 np1 np2 np4, repeated), printing per run the wall
# time, the CPU seconds, the parallel efficiency against 1x2 (eff = wall(1x2) / wall(run); 1 =
# the same wall time on the same cores), the CPU efficiency (cpu_eff = cpu(1x2) / cpu(run):
# the share of the CPU time spent as the single process would; what a shared machine's noise
# disturbs least), and from rank 0's --stats the busy time of each rank, the
# imbalance (1 - mean busy / max busy), the bytes gathered and rank 0's receive and write
# time. Every image of every run is checked byte-identical to the 1x2 one.
#
# usage: bench/mpi_bench.sh [BUILD_DIR] [--scale F] [--spp N] [--reps N]
# Defaults: build, scale 0.2 (200x200 frames, the large image at twice that), 16 spp, 2 reps.
set -uo pipefail
build=build
scale=0.2
spp=16
reps=2
while [ $# -gt 0 ]; do
  case "$1" in
    --scale) scale="$2"; shift 2 ;;
    --spp) spp="$2"; shift 2 ;;
    --reps) reps="$2"; shift 2 ;;
    *) build="$1"; shift ;;
  esac
done
here="$(cd "$(dirname "$0")/.." && pwd)"
rt="$build/raytracer"
frames=("$here"/../shared/scenes/hw3/tap_water/xml/tap_0*.xml)
[ -x "$rt" ] || { echo "no $rt (build first)"; exit 1; }
[ -f "${frames[0]}" ] || { echo "the tap-water frames are missing (../shared/scenes)"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,vader
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
large_scale=$(awk -v s="$scale" 'BEGIN { print 2 * s }')

echo "machine: $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "frames: ${#frames[@]} tap-water frames at scale $scale; large: tap_0000 at scale $large_scale; $spp spp; CPU reference"
printf '%-7s %-5s %3s %8s %8s %7s %7s %8s %12s %8s %8s  %s\n' job run rep wall_s cpu_s eff cpu_eff imbal gathered recv_s write_s "busy per rank, s (tasks)"

# run JOB CONFIG REP: renders and prints one table row.
declare -A base cbase
run() {
  local job="$1" config="$2" rep="$3" out="$work/$1.$2.$3"
  local -a scenes flags=(--spp "$spp" --device cpu --quiet --stats)
  if [ "$job" = frames ]; then scenes=("${frames[@]}"); flags+=(--resolution-scale "$scale")
  else scenes=("${frames[0]}"); flags+=(--resolution-scale "$large_scale"); fi
  mkdir -p "$out"
  local -a cmd
  case "$config" in
    1x2) cmd=("$rt" "${scenes[@]}" "${flags[@]}" --threads 2) ;;
    np1) cmd=(mpirun --bind-to none -np 1 "$rt" "${scenes[@]}" "${flags[@]}") ;;
    np2) cmd=(mpirun --bind-to none -np 2 "$rt" "${scenes[@]}" "${flags[@]}") ;;
    np4) cmd=(mpirun --oversubscribe --bind-to none -np 4 "$rt" "${scenes[@]}" "${flags[@]}") ;;
  esac
  local t0 t1
  t0=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$out.time" "${cmd[@]}" --output-dir "$out" 2> "$out.err" ||
    { echo "$job $config failed: $(tail -3 "$out.err")"; return; }
  t1=$(date +%s.%N)
  local wall cpu
  wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
  cpu=$(awk '{ printf "%.2f", $1 + $2 }' "$out.time")
  if [ "$config" = 1x2 ]; then base[$job.$rep]=$wall; cbase[$job.$rep]=$cpu; fi
  for f in "$work/$job.1x2.$rep"/*; do
    cmp -s "$f" "$out/$(basename "$f")" || echo "  DIFFERENT: $out/$(basename "$f")"
  done
  local eff ceff stats
  eff=$(awk -v a="${base[$job.$rep]}" -v b="$wall" 'BEGIN { printf "%.2f", a / b }')
  ceff=$(awk -v a="${cbase[$job.$rep]}" -v b="$cpu" 'BEGIN { printf "%.2f", a / b }')
  stats=$(grep "^stats: mpi:" "$out.err")
  if [ -n "$stats" ]; then
    local imbal gathered recv write busy
    imbal=$(sed -E 's/.*imbalance ([0-9.]+) %.*/\1%/' <<< "$stats")
    gathered=$(sed -E 's/.*gathered ([0-9]+) bytes in ([0-9.]+) s.*/\1/' <<< "$stats")
    recv=$(sed -E 's/.*gathered [0-9]+ bytes in ([0-9.]+) s.*/\1/' <<< "$stats")
    write=$(sed -E 's/.*writing ([0-9.]+) s.*/\1/' <<< "$stats")
    busy=$(sed -E 's/.*busy per rank: //' <<< "$stats")
    printf '%-7s %-5s %3s %8s %8s %7s %7s %8s %12s %8s %8s  %s\n' "$job" "$config" "$rep" "$wall" "$cpu" "$eff" "$ceff" "$imbal" "$gathered" "$recv" "$write" "$busy"
  else
    printf '%-7s %-5s %3s %8s %8s %7s %7s %8s %12s %8s %8s\n' "$job" "$config" "$rep" "$wall" "$cpu" "$eff" "$ceff" - - - -
  fi
}

for rep in $(seq 1 "$reps"); do
  for job in frames large; do
    for config in 1x2 np1 np2 np4; do run "$job" "$config" "$rep"; done
  done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
