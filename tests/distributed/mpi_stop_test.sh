#!/bin/bash
# Stopping, checkpointing and resuming under mpirun -np 2, through the executable
# (src/distributed/, docs/distributed.md). The scene is tests/resume/tiny.xml at 128x64 in
# tiles of 32 rows; every signal is sent once the job has shown it renders (its first
# checkpoint file), never after a fixed sleep.
#
# usage: mpi_stop_test.sh RAYTRACER MPIEXEC SCENE WORKDIR CASE cpu|cl
# sigint:     SIGINT to rank 0: status 130, "written with N of 2000 samples per pixel and its
#             checkpoint", the image and moments marked partial, no temporary file; then
#             --resume under mpirun (whole images) gives the bytes of one uninterrupted
#             process, and the checkpoint is gone.
# sigterm:    the same with SIGTERM (143), resumed in tiles.
# mpirun:     SIGINT to mpirun itself, which sends SIGTERM to the ranks
#             odls_base_sigkill_timeout seconds later (3 here) and SIGKILL as long after:
#             the ranks write the partial image and its checkpoint in that window; mpirun's
#             own status is 1.
# checkpoint: --checkpoint 0.1 under mpirun writes checkpoints while it runs; a copy of one
#             (with its partial image) taken mid-run is continued by --resume under mpirun to
#             the bytes of one process; one process refuses it when its bands hold different
#             counts.
# progress:   a resumed render's progress starts at its checkpoint's samples: one process's
#             first line shows at least them, the job line under mpirun more than 0 %.
# notice:     (SCENE: hw3's cornellbox_boxes_dynamic.xml) the --cull-back-faces notice is
#             printed once under mpirun, the image in tiles; not with --cull-back-faces.
# Exit status: 0 pass, 1 fail, 77 skipped (no OpenCL device, no scene).
set -uo pipefail
rt="$1" mpiexec="$2" scene="$3" work="$4" case="$5" device="$6"
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=../support/mpi_setup.sh
source "$here/../support/mpi_setup.sh"
rm -rf "$work" && mkdir -p "$work/ref" || fail "cannot create $work"
cd "$work" || exit 1
flags=(--device "$device" --resolution-scale 8 --seed 5 --moments --threads 1 --spp 2000)
mpi=("$mpiexec" --oversubscribe --bind-to none -np 2)

reference() {
  "$rt" "$scene" "${flags[@]}" --quiet --output-dir ref || fail "the reference render failed"
}
# wait_for FILE PID: until FILE exists (the job renders) or the job ends.
wait_for() {
  for _ in $(seq 6000); do
    [ -e "$1" ] && return 0
    kill -0 "$2" 2> /dev/null || fail "the job ended before writing $1: $(cat ./*.err 2> /dev/null)"
    sleep 0.01
  done
  fail "no $1 after 60 s"
}
# rank0 MPIRUN_PID: the pid of rank 0 (OMPI_COMM_WORLD_RANK=0 in its environment).
rank0() {
  for _ in $(seq 500); do
    for p in $(pgrep -P "$1"); do
      tr '\0' '\n' < "/proc/$p/environ" 2> /dev/null | grep -qx OMPI_COMM_WORLD_RANK=0 && echo "$p" && return
    done
    sleep 0.01
  done
}
# check_partial DIR ERRFILE: the written-with line, partial marks, a checkpoint, no temporary.
check_partial() {
  grep -Eq "^raytracer: interrupted: $1/simple.png written with [0-9]+ of 2000 samples per pixel and its checkpoint $1/simple.png.rtcheckpoint$" "$2" ||
    fail "no 'written with N of 2000' line: $(cat "$2")"
  grep -aq "rt:samples" "$1/simple.png" || fail "$1/simple.png is not marked partial"
  grep -aq "rt:samples" "$1/simple.moments.exr" || fail "$1/simple.moments.exr is not marked partial"
  [ -e "$1/simple.png.rtcheckpoint" ] || fail "no checkpoint in $1"
  ! ls -A "$1" | grep -q '^\.rt-' || fail "a temporary file was left in $1"
}
# resume_identical DIR [FLAGS...]: --resume under mpirun -np 2 ends with the reference's bytes.
resume_identical() {
  local dir="$1"
  shift
  "${mpi[@]}" "$rt" "$scene" "${flags[@]}" --quiet "$@" --output-dir "$dir" --resume 2> "$dir.resume.err" ||
    fail "mpirun --resume failed: $(cat "$dir.resume.err")"
  for f in simple.png simple.moments.exr; do
    cmp -s "$dir/$f" "ref/$f" || fail "$dir/$f differs from the uninterrupted render"
  done
  [ ! -e "$dir/simple.png.rtcheckpoint" ] || fail "the checkpoint in $dir was not removed"
}
# stop_rank0 SIGNAL STATUS DIR: the job in tiles, SIGNAL to rank 0 once it checkpoints.
stop_rank0() {
  mkdir -p "$3"
  "${mpi[@]}" "$rt" "$scene" "${flags[@]}" --tile-rows 32 --checkpoint 0.05 --output-dir "$3" 2> "$3.err" &
  local pid=$!
  wait_for "$3/simple.png.rtcheckpoint" "$pid"
  local r0
  r0=$(rank0 "$pid")
  [ -n "$r0" ] || fail "rank 0 not found"
  kill "-$1" "$r0"
  wait "$pid"
  local status=$?
  [ "$status" = "$2" ] || fail "SIG$1 to rank 0: status $status, not $2: $(cat "$3.err")"
  check_partial "$3" "$3.err"
}

case "$case" in
  sigint)
    reference
    stop_rank0 INT 130 int
    resume_identical int
    echo "ok: SIGINT to rank 0: 130, partial image and checkpoint; --resume byte-identical"
    ;;
  sigterm)
    reference
    stop_rank0 TERM 143 term
    resume_identical term --tile-rows 32
    echo "ok: SIGTERM to rank 0: 143, partial image and checkpoint; --resume in tiles byte-identical"
    ;;
  mpirun)
    mkdir -p job
    flags=(--device "$device" --resolution-scale 8 --seed 5 --moments --threads 1 --spp 400000)
    OMPI_MCA_odls_base_sigkill_timeout=3 "${mpi[@]}" "$rt" "$scene" "${flags[@]}" --tile-rows 32 \
      --checkpoint 0.05 --output-dir job 2> job.err &
    pid=$!
    wait_for job/simple.png.rtcheckpoint "$pid"
    kill -INT "$pid"
    wait "$pid"
    status=$?
    [ "$status" = 1 ] || fail "SIGINT to mpirun: status $status, not mpirun's 1: $(cat job.err)"
    grep -Eq "^raytracer: interrupted: job/simple.png written with [0-9]+ of 400000 samples per pixel and its checkpoint job/simple.png.rtcheckpoint$" job.err ||
      fail "no 'written with N of 400000' line: $(cat job.err)"
    grep -aq "rt:samples" job/simple.png || fail "job/simple.png is not marked partial"
    ! ls -A job | grep -q '^\.rt-' || fail "a temporary file was left"
    echo "ok: SIGINT to mpirun: the ranks wrote the partial image and checkpoint; mpirun's status 1"
    ;;
  checkpoint)
    reference
    mkdir -p run copy
    "${mpi[@]}" "$rt" "$scene" "${flags[@]}" --tile-rows 32 --checkpoint 0.1 --output-dir run 2> run.err &
    pid=$!
    # A checkpoint whose every row holds samples, copied with its image (image first: the
    # checkpoint, written first, is then at least as new).
    for _ in $(seq 6000); do
      if [ -e run/simple.png.rtcheckpoint ]; then
        cp run/simple.png run/simple.moments.exr copy/ 2> /dev/null
        cp run/simple.png.rtcheckpoint copy/ 2> /dev/null
        spp=$(head -c 4096 copy/simple.png.rtcheckpoint 2> /dev/null | grep -a '^spp ' | cut -d' ' -f2)
        [ -e copy/simple.png ] && [ -n "$spp" ] && [ "$spp" -gt 0 ] && break
      fi
      kill -0 "$pid" 2> /dev/null || fail "the job ended before a checkpoint with samples: $(cat run.err)"
      sleep 0.01
    done
    [ -n "${spp:-}" ] && [ "$spp" -gt 0 ] || fail "no checkpoint with samples"
    [ "$spp" -lt 2000 ] || fail "the checkpoint holds every sample"
    grep -aq "rt:samples" copy/simple.png || fail "the image beside the checkpoint is not marked partial"
    wait "$pid" || fail "the checkpointing job failed: $(cat run.err)"
    cmp -s run/simple.png ref/simple.png || fail "the checkpointing job's image differs from one process's"
    [ ! -e run/simple.png.rtcheckpoint ] || fail "the finished job left its checkpoint"
    if head -c 4096 copy/simple.png.rtcheckpoint | grep -aq '^rows '; then
      "$rt" "$scene" "${flags[@]}" --output-dir copy --resume 2> one.err &&
        fail "one process continued a checkpoint whose bands hold different counts"
      grep -q "continue it under mpirun" one.err || fail "the refusal does not say why: $(cat one.err)"
    fi
    resume_identical copy
    echo "ok: --checkpoint under mpirun at $spp spp, continued by --resume byte-identical"
    ;;
  progress)
    pty() { python3 "$here/../app/pty_run.py" "$@"; }
    mkdir -p one
    "$rt" "$scene" "${flags[@]}" --checkpoint 0.05 --output-dir one 2> one.err &
    pid=$!
    wait_for one/simple.png.rtcheckpoint "$pid"
    kill -INT "$pid"
    wait "$pid"
    [ $? = 130 ] || fail "the one-process render was not interrupted"
    saved=$(head -c 4096 one/simple.png.rtcheckpoint | grep -a '^spp ' | cut -d' ' -f2)
    cp -r one job
    pty one.txt "$rt" "$scene" "${flags[@]}" --output-dir one --resume > /dev/null || fail "the resumed render failed"
    first=$(tr '\r' '\n' < one.txt | grep -Eo '^simple.png: [0-9]+ of 2000 spp|\] simple.png: [0-9]+ of 2000 spp' | head -1 | grep -Eo '[0-9]+ of' | cut -d' ' -f1)
    [ -n "$first" ] || fail "no progress line: $(head -c 400 one.txt)"
    [ "$first" -ge "$saved" ] || fail "the resumed progress started at $first spp, below the checkpoint's $saved"
    pty job.txt "${mpi[@]}" "$rt" "$scene" "${flags[@]}" --output-dir job --resume > /dev/null || fail "mpirun --resume failed"
    pct=$(tr '\r' '\n' < job.txt | sed 's/\x1b\[K//g' | grep -Eo '^job: .*\(([0-9.]+) %\)' | head -1 | sed -E 's/.*\(([0-9.]+) %\)/\1/')
    [ -n "$pct" ] || fail "no job line: $(head -c 400 job.txt)"
    awk -v p="$pct" 'BEGIN { exit !(p > 0) }' || fail "the resumed job's line started at $pct %"
    echo "ok: resumed progress starts at $first spp (checkpoint $saved) and at $pct % under mpirun"
    ;;
  notice)
    [ -f "$scene" ] || { echo "SKIP: $scene is not present (the course's scenes live in ../shared/scenes)"; exit 77; }
    mkdir -p out
    box=("${mpi[@]}" "$rt" "$scene" --device "$device" --resolution-scale 0.25 --spp 1 --tile-rows 32 --output-dir out)
    "${box[@]}" > /dev/null 2> err.txt || fail "mpirun failed: $(cat err.txt)"
    [ "$(grep -c '^notice: .*--cull-back-faces' err.txt)" = 1 ] || fail "expected one --cull-back-faces notice, got: $(cat err.txt)"
    grep -Eq '^notice: out/cornellbox_boxes_dynamic.png: [0-9]+ % of camera rays first hit the back of a surface' err.txt ||
      fail "the notice does not say what it found: $(cat err.txt)"
    "${box[@]}" --cull-back-faces > /dev/null 2> err2.txt || fail "mpirun --cull-back-faces failed"
    ! grep -q 'cull-back-faces' err2.txt || fail "the notice was given with --cull-back-faces: $(cat err2.txt)"
    echo "ok: the back-face notice once under mpirun"
    ;;
  *) fail "unknown case $case" ;;
esac
exit 0
