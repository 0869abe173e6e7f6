#!/bin/sh
# Runs one libFuzzer target of the sanitized tree (tools/sanitize_build.sh) from its seed corpus:
# fuzz/seeds/TARGET, fuzz/regressions/TARGET (and the dictionary fuzz/TARGET.dict), and for
# scene, ply, png and jpeg every course file of that kind under ../shared/scenes of at most
# 64 KiB (the command line's seeds add each course scene's flags from tests/course/course_scenes.txt).
# A crash leaves its input in BUILD_DIR/fuzz-artifacts/TARGET/; after the fix, copy it into
# fuzz/regressions/TARGET/, where the unit tests replay it.
#
# usage: tools/fuzz.sh BUILD_DIR TARGET SECONDS [CORPUS_DIR]
#   TARGET: scene ply cli png jpeg exr hdr obj gltf (fuzz/targets.h says what each reads).
#   The default suite runs each target for 25 s with a throw-away corpus. A long run keeps a
#   corpus outside the repository between runs, stops at a number of executions per process
#   (RT_FUZZ_RUNS) and may shard over RT_FUZZ_JOBS processes sharing that corpus, e.g. 10
#   million executions over 2 processes, at the lowest priority:
#     RT_FUZZ_RUNS=5000000 RT_FUZZ_JOBS=2 nice -n 19 tools/fuzz.sh build/sanitize scene 36000 \
#       /tmp/fuzz-corpus/scene
#   Each process then logs to BUILD_DIR/fuzz-artifacts/TARGET/job-N.log; the script prints
#   every log's final statistics.
set -eu
dir=$1 target=$2 seconds=$3 corpus=${4:-}
fuzzer=$dir/fuzz/fuzz_$target
if [ ! -x "$fuzzer" ]; then
  echo "skipped: $fuzzer was not built (clang missing? see the output of sanitize.build)"
  exit 77
fi
src=$(cd "$(dirname "$0")/.." && pwd)
shared=$src/../shared/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seeds=$work/seeds
mkdir -p "$seeds"
for d in "$src/fuzz/seeds/$target" "$src/fuzz/regressions/$target"; do
  [ -d "$d" ] && find "$d" -type f -exec cp -t "$seeds" {} +
done
case $target in
  scene | ply | png | jpeg)
    if [ -d "$shared" ]; then
      case $target in scene) ext=xml ;; jpeg) ext=jpg ;; *) ext=$target ;; esac
      i=0
      find "$shared" -name "*.$ext" -size -65k | while read -r f; do
        i=$((i + 1))
        cp "$f" "$seeds/course_$i"
      done
    fi ;;
  cli)
    i=0
    grep -v '^#' "$src/tests/course/course_scenes.txt" | while read -r _ scene _ _ flags; do
      i=$((i + 1))
      # shellcheck disable=SC2086  # the flags are split on purpose
      printf '%s\0' "$scene" $flags > "$seeds/course_$i"
    done ;;
esac
[ -n "$corpus" ] || corpus=$work/corpus
mkdir -p "$corpus" "$dir/fuzz-artifacts/$target"
runs=${RT_FUZZ_RUNS:--1}
dict=""
[ -f "$src/fuzz/$target.dict" ] && dict="-dict=$src/fuzz/$target.dict"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
case $target in
  obj | gltf) export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$src/fuzz/assimp_lsan.supp}" ;;
esac
jobs=${RT_FUZZ_JOBS:-1}
echo "fuzz_$target: $(ls "$seeds" | wc -l) seeds, ${seconds} s, $jobs process(es), corpus $corpus"
# -max_len bounds the inputs (the seeds are at most 64 KiB); -timeout flags any input that
# takes 10 s as a hang; -rss_limit_mb any that needs 2 GiB (RT_FUZZ_RSS_MB: lower it when many
# processes share the machine's memory).
set -- -max_total_time="$seconds" -runs="$runs" -max_len=65536 -timeout=10 \
  -rss_limit_mb="${RT_FUZZ_RSS_MB:-2048}" \
  -print_final_stats=1 -artifact_prefix="$dir/fuzz-artifacts/$target/"
set +e
if [ "$jobs" -le 1 ]; then
  # shellcheck disable=SC2086  # $dict is empty or one word
  "$fuzzer" $dict "$@" "$corpus" "$seeds"
  status=$?
else
  # The seeds join the shared corpus once; then every process mutates that one folder and
  # picks up what the others add (libFuzzer rereads it, -reload=1).
  # shellcheck disable=SC2086
  "$fuzzer" $dict -max_len=65536 -merge=1 -artifact_prefix="$dir/fuzz-artifacts/$target/" \
    "$corpus" "$seeds" >"$dir/fuzz-artifacts/$target/merge.log" 2>&1
  pids=""
  for j in $(seq 1 "$jobs"); do
    # shellcheck disable=SC2086
    "$fuzzer" $dict "$@" -reload=1 "$corpus" >"$dir/fuzz-artifacts/$target/job-$j.log" 2>&1 &
    pids="$pids $!"
  done
  status=0
  for p in $pids; do wait "$p" || status=1; done
  for j in $(seq 1 "$jobs"); do
    echo "-- job $j:"
    grep -E '^(#[0-9]+.*DONE|stat::|==[0-9]+==ERROR|SUMMARY)' "$dir/fuzz-artifacts/$target/job-$j.log"
  done
fi
[ $status -eq 0 ] || echo "fuzz_$target failed; its input is in $dir/fuzz-artifacts/$target/"
exit $status
