#!/bin/sh
# Runs one libFuzzer target of the sanitized tree (tools/sanitize_build.sh) from its seed corpus:
# fuzz/seeds/TARGET, fuzz/regressions/TARGET (and the dictionary fuzz/TARGET.dict), and for scene and ply every course file under
# ../shared/scenes of at most 64 KiB (the command line's seeds add each course scene's flags
# from tests/course/course_scenes.txt). A crash leaves its input in BUILD_DIR/fuzz-artifacts/TARGET/;
# after the fix, copy it into fuzz/regressions/TARGET/, where the unit tests replay it.
#
# usage: tools/fuzz.sh BUILD_DIR scene|ply|cli SECONDS [CORPUS_DIR]
#   The default suite runs each target for 25 s with a throw-away corpus. A long run keeps a
#   corpus between runs and may stop at a number of executions, e.g. for 10 million:
#     RT_FUZZ_RUNS=10000000 tools/fuzz.sh build/sanitize scene 36000 fuzz-corpus/scene
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
  scene | ply)
    if [ -d "$shared" ]; then
      ext=xml
      [ "$target" = ply ] && ext=ply
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
echo "fuzz_$target: $(ls "$seeds" | wc -l) seeds, ${seconds} s, corpus $corpus"
# -max_len bounds the inputs (the seeds are at most 64 KiB); -timeout flags any input that
# takes 10 s as a hang; -rss_limit_mb any that needs 2 GiB.
set +e
# shellcheck disable=SC2086  # $dict is empty or one word
"$fuzzer" $dict -max_total_time="$seconds" -runs="$runs" -max_len=65536 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/fuzz-artifacts/$target/" \
  "$corpus" "$seeds"
status=$?
[ $status -eq 0 ] || echo "fuzz_$target failed; its input is in $dir/fuzz-artifacts/$target/"
exit $status
