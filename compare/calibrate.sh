#!/bin/bash
# The full calibration of `compare` (CTest runs a small version: compare.calibration).
# For each configuration it renders the scene N times on the CPU and prints a table of
# false-alarm rates (A vs A, different seeds) and detection rates of planted biases
# (a light 2 % brighter, roughness 10 % larger, the camera one pixel to the right), with
# 95 % Clopper-Pearson intervals, and the per-test rejection rates under H0.
# About 15 minutes on 2 cores.
#
# usage: compare/calibrate.sh [BUILD_DIR] [TRIAL_FACTOR]
#   TRIAL_FACTOR scales every trial count (e.g. 0.1 for a quick look).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
factor="${2:-1}"
cal="$build/compare_calibrate"
shared="$here/../shared/scenes"
trials() { awk -v n="$1" -v f="$factor" 'BEGIN { t = int(n * f); print t < 2 ? 2 : t }'; }
run() {  # SCENE TRIALS ARGS...
  local scene="$1" n="$2"
  shift 2
  if [ ! -f "$scene" ]; then
    echo "skipped: $scene is not present"
    return
  fi
  echo
  "$cal" "$scene" --trials "$(trials "$n")" --threads "$(nproc)" --alpha 0.01,0.05 "$@" \
    2> /dev/null | grep -v '^welch-bh.*\(light\|roughness\|camera\)' || true
}

ex="$here/scenes/example.xml"
# The scene's own 36 spp (a 6x6 stratified pattern) and 35 spp (independent samples).
run "$ex" 200 --scale 0.1 --tiles 1,8
run "$ex" 500 --scale 0.1 --spp 35 --tiles 1,8
# A larger image: 20x the cells, so the uniformity check sees any misfit of the t model.
run "$ex" 20 --scale 0.5 --spp 35 --tiles 1,8
# A scene whose roughness matters: large brushed-metal surfaces, at its own 400 spp
# (stratified) and at 399 (independent).
run "$shared/hw3/cornellbox_brushed_metal.xml" 20 --scale 0.1 --tiles 1,8
run "$shared/hw3/cornellbox_brushed_metal.xml" 20 --scale 0.1 --spp 399 --tiles 1,8
