#!/bin/bash
# The path tracer against the course's 16 path-traced references (hw6/pathTracing, two
# scenes x 8 cameras): one table row per camera from build/path_reference (see its header
# for the columns). Rendering all of every image at 100 spp takes about 1.5 minutes per
# camera on 2 cores; BUDGET samples per camera render a regular subset of 4x4 blocks.
#
# usage: bench/path_reference.sh [BUDGET]   (default 2e6, 6.2 % of the pixels; 0: all)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
shared="$here/../shared/scenes/hw6"
budget="${1:-2e6}"
args=()
[ "$budget" != 0 ] && args=(--budget "$budget")
for scene in diffuse glass; do
  "$here/build/path_reference" "$shared/pathTracing/cornellbox_jaroslav_path_$scene.xml" \
    "$shared/reference/pathTracing" "${args[@]}"
done
