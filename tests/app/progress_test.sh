#!/bin/bash
# What the raytracer tells the person running it (src/app/progress.h), checked on the
# bytes a terminal receives (tests/app/pty_run.py gives the run a pseudo-terminal).
#
# usage: progress_test.sh RAYTRACER SCENES_DIR WORKDIR CASE [DEVICE|MPIEXEC]
# live DEVICE: two scene files, three cameras: every live line reads
#              "[k/n] NAME: S of N spp (P %), elapsed E, R Mrays/s, left L" with R > 0 and
#              k/n running to 3/3; the loading and BVH status show; on cl the kernel
#              compile is announced, then "kernel from cache" on a second run; each image
#              ends with "wrote FILE (S spp, T s)".
# silent:      --quiet on a terminal prints nothing, and without a terminal neither does a
#              successful render (the wrote lines belong to the progress they end).
# mpi MPIEXEC: under mpirun -np 2 on a terminal rank 0 draws the job-wide line and the
#              wrote lines; without a terminal, nothing.
# notice:      cornellbox_boxes_dynamic (camera outside the box's front wall) prints the
#              one --cull-back-faces notice (100 % of camera rays hit a back face); not
#              with --cull-back-faces or --quiet, nor for hw1/cornellbox, which doesn't
#              need it. Of the 75 course scenes of tests/course/course_scenes.txt rendered
#              without culling (74 load; trex_smooth lacks a PLY file) only hw3's and
#              spring2021's cornellbox_boxes_dynamic print it, both rendered by the course
#              with --cull-back-faces (the shares: src/app/backface_notice.h).
# Exit status: 0 pass, 1 fail, 77 skipped (no OpenCL device, no scenes, no MPI).
set -uo pipefail
rt="$1" scenes="$2" work="$3" case="$4" arg="${5:-}"
here="$(cd "$(dirname "$0")" && pwd)"
pty() { python3 "$here/pty_run.py" "$@"; }
fail() {
  echo "FAIL: $*"
  exit 1
}
skip() {
  echo "SKIP: $*"
  exit 77
}
need() {
  for s in "$@"; do
    [ -f "$scenes/$s" ] || skip "$scenes/$s is not present (the course's scenes live in ../shared/scenes)"
  done
}
# lines FILE: the output split at \r and \n, erase-line escapes removed, blank lines dropped.
lines() { tr '\r' '\n' < "$1" | sed 's/\x1b\[K//g' | grep -v '^$'; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot create $work"
cd "$work" || exit 1
export XDG_CACHE_HOME="$work/cache"  # An empty kernel cache: the first run compiles.
car=hw1/akif_uslu/car_smooth_fixed.xml simple=hw1/simple.xml

case "$case" in
  live)
    device="$arg"
    need "$car" "$simple"
    if [ "$device" = cl ] && ! "$rt" --list-devices > /dev/null 2>&1; then skip "no OpenCL device"; fi
    mkdir -p out
    pty run1.txt "$rt" "$scenes/$car" "$scenes/$simple" --device "$device" --resolution-scale 0.25 \
      --spp 64 --output-dir out || fail "the render failed: $(lines run1.txt | tail -3)"
    lines run1.txt > run1.lines
    re='^\[([1-3])/3\] [A-Za-z_]+\.png: [0-9]+ of 64 spp \([0-9.]+ %\), elapsed [0-9.]+ s, ([0-9.]+) Mrays/s, left [0-9.]+ s$'
    grep -Eq "$re" run1.lines || fail "no progress line of the form [k/3] NAME: S of 64 spp (P %), elapsed E, R Mrays/s, left L in: $(head -c 600 run1.lines)"
    grep -E "$re" run1.lines | sed -E "s#$re#\2#" > rates.txt || fail "cannot read the rates"
    [ "$(wc -l < rates.txt)" = "$(grep -Ec "$re" run1.lines)" ] || fail "cannot read the rates"
    zero=$(awk '$1 <= 0' rates.txt | wc -l)
    [ "$zero" = 0 ] || fail "$zero progress lines show 0 Mrays/s: $(grep -m1 ' 0.00 Mrays/s' run1.lines)"
    for k in "1/3] Car_smooth.png" "2/3] Car_front_smooth.png" "3/3] simple.png"; do
      grep -Fq "[$k: " run1.lines || fail "no progress line for [$k"
    done
    grep -Fxq "loading $scenes/$car..." run1.lines || fail "no status while loading $car"
    grep -Fxq "building the BVH of $scenes/$simple..." run1.lines || fail "no status while building the BVH"
    for f in Car_smooth Car_front_smooth simple; do
      grep -Eq "^wrote out/$f\.png \(64 spp, [0-9.]+ s\)$" run1.lines || fail "no 'wrote out/$f.png (64 spp, T s)' line"
    done
    if [ "$device" = cl ]; then
      grep -Fq "compiling the OpenCL kernel for this scene's features (cached for later runs)..." run1.lines ||
        fail "the kernel compile was not announced"
      pty run2.txt "$rt" "$scenes/$simple" --device cl --resolution-scale 0.25 --spp 4 --output-dir out ||
        fail "the second render failed"
      lines run2.txt | grep -q "^kernel from cache" || fail "the second run did not say 'kernel from cache'"
    fi
    echo "ok: live line, status, [k/n] and wrote lines on $device"
    ;;
  silent)
    need "$car"
    mkdir -p out
    pty quiet.txt "$rt" "$scenes/$car" --device cpu --resolution-scale 0.25 --spp 8 --output-dir out --quiet ||
      fail "the quiet render failed"
    [ ! -s quiet.txt ] || fail "--quiet printed on a terminal: $(head -c 300 quiet.txt | od -c | head -3)"
    "$rt" "$scenes/$car" --device cpu --resolution-scale 0.25 --spp 8 --output-dir out 2> log.txt ||
      fail "the render to a log failed"
    [ ! -s log.txt ] || fail "without a terminal stderr should stay empty, got: $(od -c log.txt | head -5)"
    echo "ok: silent with --quiet, and without a terminal"
    ;;
  mpi)
    mpiexec="$arg"
    [ -n "$mpiexec" ] && [ -x "$mpiexec" ] || skip "built without MPI (install libopenmpi-dev and reconfigure)"
    need "$car"
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
    mpi=("$mpiexec" --oversubscribe --bind-to none -np 2 "$rt" "$scenes/$car" --device cpu
         --resolution-scale 0.25 --spp 16)
    mkdir -p tty log
    pty tty.txt "${mpi[@]}" --output-dir tty || fail "mpirun failed: $(lines tty.txt | tail -3)"
    lines tty.txt > tty.lines
    grep -Eq '^job: [0-9]+ of [0-9]+ (tiles|images), [0-2] of 2 images written \([0-9.]+ %\), elapsed [0-9.]+ s, left' tty.lines ||
      fail "no job-wide line under mpirun on a terminal: $(head -c 400 tty.lines)"
    grep -Eq '^job: 0 of [0-9]+ (tiles|images), 0 of 2' tty.lines || fail "the job line never showed the start"
    for f in Car_smooth Car_front_smooth; do
      grep -Eq "^wrote tty/$f\.png \(16 spp, [0-9.]+ s\)$" tty.lines || fail "no wrote line for $f under mpirun"
    done
    "${mpi[@]}" --output-dir log > log.out 2> log.txt || fail "mpirun to a log failed"
    ! grep -q "job:" log.txt || fail "the job line was drawn without a terminal"
    ! grep -q '^wrote' log.txt || fail "wrote lines without a terminal: $(cat log.txt)"
    echo "ok: job-wide line and wrote lines under mpirun, none in a log"
    ;;
  notice)
    box=hw3/cornellbox_boxes_dynamic.xml
    need "$box" hw1/cornellbox.xml
    mkdir -p out
    run() { "$rt" "$scenes/$1" --device cpu --resolution-scale 0.25 --spp 1 --output-dir out "${@:2}" 2> "$work/err.txt"; }
    run "$box" || fail "rendering $box failed: $(cat err.txt)"
    [ "$(grep -c '^notice: .*--cull-back-faces' err.txt)" = 1 ] || fail "$box: expected one --cull-back-faces notice, got: $(cat err.txt)"
    grep -Eq '^notice: out/cornellbox_boxes_dynamic.png: [0-9]+ % of camera rays first hit the back of a surface; the course rendered such scenes with --cull-back-faces' err.txt ||
      fail "the notice does not say what it found: $(cat err.txt)"
    run "$box" --cull-back-faces || fail "rendering $box with culling failed"
    ! grep -q "notice" err.txt || fail "notice printed with --cull-back-faces: $(cat err.txt)"
    run "$box" --quiet || fail "rendering $box --quiet failed"
    [ ! -s err.txt ] || fail "--quiet printed: $(cat err.txt)"
    run hw1/cornellbox.xml || fail "rendering hw1/cornellbox.xml failed"
    ! grep -q "notice" err.txt || fail "hw1/cornellbox.xml does not need culling, yet: $(cat err.txt)"
    echo "ok: the back-face notice where culling changes the view, and only there"
    ;;
  *) fail "unknown case $case" ;;
esac
