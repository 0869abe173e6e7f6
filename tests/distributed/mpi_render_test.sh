#!/bin/bash
# The distributed driver under mpirun (src/distributed/), against the single-process render.
#
# usage: mpi_render_test.sh RAYTRACER MPIEXEC SCENES_DIR WORKDIR cpu|cl multicam|large|fault
#                           [FAULTY_RAYTRACER]
# multicam: a two-camera scene rendered by 2 and 3 ranks (whole images, then tiles of 32 rows)
#           gives byte-identical PNGs and moment files.
# large:    one image cut into tiles (automatic for 3 ranks, 64 rows for 2) is byte-identical.
# fault:    seven frames; rank 1 killed at its second task ends the job non-zero, naming the
#           rank, with no partial or temporary file; rank 2 failing ends it with one line
#           from rank 0; --skip-existing then renders only the missing frames, and every frame
#           is byte-identical to the single-process one. The faults are injected by
#           FAULTY_RAYTRACER (raytracer_mpi_faults, built with the RT_MPI_FAULT hook); the
#           raytracer itself ignores RT_MPI_FAULT and renders every frame.
# Ranks are oversubscribed (the suite runs on 2 cores) and allowed to run as root.
# Exit status: 0 pass, 1 fail, 77 skipped (no OpenCL device, or the scenes are missing).
set -uo pipefail
rt="$1" mpiexec="$2" scenes="$3" work="$4" device="$5" case="$6" faulty="${7:-}"
exe="$rt"  # the executable run() starts; the fault case swaps in $faulty
# shellcheck source=../support/mpi_setup.sh
source "$(dirname "$0")/../support/mpi_setup.sh"
rm -rf "$work" && mkdir -p "$work" || fail "cannot create $work"

# run DIR NP [flags...]: renders into DIR (created) with NP ranks, 0 meaning no mpirun;
# stderr goes to DIR.err, and the exit status is returned.
run() {
  local dir="$1" np="$2"
  shift 2
  mkdir -p "$dir"
  if [ "$np" = 0 ]; then
    "$exe" "${scene_args[@]}" --device "$device" --output-dir "$dir" --quiet "$@" 2> "$dir.err"
  else
    "$mpiexec" --oversubscribe --bind-to none -np "$np" "$exe" "${scene_args[@]}" \
      --device "$device" --output-dir "$dir" --quiet "$@" 2> "$dir.err"
  fi
}

# same DIR: every file of the single-process render is in DIR with the same bytes.
same() {
  local n=0
  for f in "$work/single"/*; do
    cmp -s "$f" "$1/$(basename "$f")" || fail "$1/$(basename "$f") differs from $f"
    n=$((n + 1))
  done
  [ "$(ls "$1" | wc -l)" = "$n" ] || fail "$1 holds $(ls "$1" | wc -l) files, expected $n"
  echo "ok: $1: $n files byte-identical"
}

no_temporaries() {
  if ls -a "$1" | grep -q '^\.rt-'; then fail "$1 holds a temporary file"; fi
}

case "$case" in
  multicam)
    scene_args=("$scenes/hw1/akif_uslu/car_smooth_fixed.xml")
    flags=(--resolution-scale 0.125 --spp 2 --moments)
    ;;
  large)
    scene_args=("$scenes/hw3/tap_water/xml/tap_0000.xml")
    flags=(--resolution-scale 0.25 --spp 4 --moments)
    ;;
  fault)
    [ -x "$faulty" ] || fail "the fault case needs FAULTY_RAYTRACER (raytracer_mpi_faults)"
    scene_args=("$scenes"/hw3/tap_water/xml/tap_0*.xml)
    flags=(--resolution-scale 0.1 --spp 8)
    ;;
  *) fail "unknown case $case" ;;
esac
for s in "${scene_args[@]}"; do
  [ -f "$s" ] || { echo "SKIP: $s is not present (the course's scenes live in ../shared/scenes)"; exit 77; }
done

run "$work/single" 0 "${flags[@]}" || fail "single-process render: $(cat "$work/single.err")"
case "$case" in
  multicam)
    run "$work/np2" 2 "${flags[@]}" || fail "np 2: $(cat "$work/np2.err")"
    same "$work/np2"
    run "$work/np3" 3 "${flags[@]}" || fail "np 3: $(cat "$work/np3.err")"
    same "$work/np3"
    run "$work/np3_tiles" 3 "${flags[@]}" --tile-rows 32 || fail "np 3 tiles: $(cat "$work/np3_tiles.err")"
    same "$work/np3_tiles"
    ;;
  large)
    run "$work/np3" 3 "${flags[@]}" --stats || fail "np 3: $(cat "$work/np3.err")"
    grep -q "tile rows 32" "$work/np3.err" || fail "np 3 did not cut the image: $(cat "$work/np3.err")"
    same "$work/np3"
    run "$work/np2" 2 "${flags[@]}" --tile-rows 64 || fail "np 2: $(cat "$work/np2.err")"
    same "$work/np2"
    ;;
  fault)
    # The raytracer itself has no fault hook: the same request renders every frame.
    RT_MPI_FAULT=1:kill run "$work/unhooked" 2 "${flags[@]}" --tile-rows 32 ||
      fail "RT_MPI_FAULT reached the raytracer: $(cat "$work/unhooked.err")"
    same "$work/unhooked"
    # Rank 1 dies at its second task: that frame can never be finished.
    RT_MPI_FAULT=1:kill exe="$faulty" run "$work/killed" 2 "${flags[@]}" --tile-rows 32
    status=$?
    [ "$status" != 0 ] || fail "a killed rank left exit status 0"
    grep -q "rank 1" "$work/killed.err" || fail "the killed rank is not named: $(cat "$work/killed.err")"
    no_temporaries "$work/killed"
    written=$(ls "$work/killed" | wc -l)
    [ "$written" -lt 7 ] || fail "all 7 frames written although rank 1 was killed"
    echo "ok: killed rank 1: exit $status, $written of 7 frames written"
    run "$work/killed" 2 "${flags[@]}" --skip-existing --stats || fail "resume: $(cat "$work/killed.err")"
    grep -q "| $((7 - written)) of $((7 - written)) images written" "$work/killed.err" ||
      fail "the resume did not render exactly the $((7 - written)) missing frames: $(cat "$work/killed.err")"
    same "$work/killed"
    # Rank 2's second task throws: one line from rank 0 names it.
    RT_MPI_FAULT=2:fail exe="$faulty" run "$work/failed" 3 "${flags[@]}" --tile-rows 32
    status=$?
    [ "$status" = 1 ] || fail "a failed rank gave exit status $status, not 1"
    [ "$(grep -c '^raytracer: error: rank 2: injected failure' "$work/failed.err")" = 1 ] ||
      fail "no single line from rank 0 naming rank 2: $(cat "$work/failed.err")"
    no_temporaries "$work/failed"
    run "$work/failed" 3 "${flags[@]}" --skip-existing || fail "resume: $(cat "$work/failed.err")"
    same "$work/failed"
    ;;
esac
echo "PASS"
