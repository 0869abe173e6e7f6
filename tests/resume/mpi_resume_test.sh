#!/bin/bash
# --resume under mpirun: a render interrupted in one process (its image partial, its
# checkpoint beside it) is continued by 2 ranks, whole images and tiles of 32 rows, to the
# bytes of an uninterrupted render.
#
# usage: mpi_resume_test.sh RAYTRACER MPIEXEC SCENE WORKDIR cpu|cl
# Exit status: 0 pass, 1 fail, 77 skipped (no OpenCL device).
set -uo pipefail
rt="$1" mpiexec="$2" scene="$3" work="$4" device="$5"
# shellcheck source=../support/mpi_setup.sh
source "$(dirname "$0")/../support/mpi_setup.sh"
rm -rf "$work" && mkdir -p "$work/ref" || fail "cannot create $work"
# 128x64 pixels: two tiles of 32 rows.
flags=(--device "$device" --quiet --resolution-scale 8 --seed 5 --moments --threads 1 --spp 1500)
"$rt" "$scene" "${flags[@]}" --output-dir "$work/ref" || fail "the reference render failed"
for mode in images tiles; do
  dir="$work/$mode"
  mkdir -p "$dir"
  "$rt" "$scene" "${flags[@]}" --output-dir "$dir" --checkpoint 0.05 &
  pid=$!
  for _ in $(seq 2000); do [ -e "$dir/simple.png.rtcheckpoint" ] && break; sleep 0.005; done
  kill -INT "$pid"
  wait "$pid"
  [ $? = 130 ] || fail "$mode: the interrupted render did not exit 130"
  [ -e "$dir/simple.png.rtcheckpoint" ] || fail "$mode: no checkpoint"
  cmp -s "$dir/simple.png" "$work/ref/simple.png" && fail "$mode: the partial image is whole"
  tiles=()
  [ "$mode" = tiles ] && tiles=(--tile-rows 32)
  "$mpiexec" --oversubscribe --bind-to none -np 2 "$rt" "$scene" "${flags[@]}" "${tiles[@]}" \
    --output-dir "$dir" --resume 2> "$dir.err" || fail "$mode: mpirun --resume failed: $(cat "$dir.err")"
  for f in simple.png simple.moments.exr; do
    cmp -s "$dir/$f" "$work/ref/$f" || fail "$mode: $f differs from the uninterrupted render"
  done
  [ -e "$dir/simple.png.rtcheckpoint" ] && fail "$mode: the checkpoint was not removed"
  echo "ok: $mode: resumed under mpirun -np 2, byte-identical"
done
exit 0
