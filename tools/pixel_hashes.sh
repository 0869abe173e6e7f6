#!/bin/bash
# Refactor check: renders every course scene of tests/course/course_scenes.txt, the example
# scene and tap_0200 on both devices (seed 0) and prints a SHA-256 of every PNG and
# moments file, so two builds can be compared byte for byte:
#   tools/pixel_hashes.sh BUILD_A quick > a.txt; tools/pixel_hashes.sh BUILD_B quick > b.txt
#   diff a.txt b.txt
# quick: a quarter of each resolution at 4 samples per pixel (about a minute);
# own:   a tenth of each resolution at the scene's own sample count (up to 900 samples per
#        pixel, where the stratum permutations walk cycles that 4 samples never reach; a
#        few minutes);
# full:  every scene at its own resolution and sample count.
# Scenes whose files are missing in ../shared are listed as "missing".
# Moments files record the scene's path: checkouts beside the same shared/ folder agree on
# every line but the example scene's moments (it lives inside the checkout).
# RT_PIXEL_FLAGS: extra raytracer flags for every render, e.g. to compare with a baseline
# made before the 8-bit conversion truncated by default:
#   RT_PIXEL_FLAGS="--quantize round" tools/pixel_hashes.sh build quick > b.txt
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: pixel_hashes.sh BUILD_DIR quick|own|full [device...]}" && pwd)"
mode="${2:-quick}"
shift 2 || shift $#
devices=("$@")
[ ${#devices[@]} -eq 0 ] && devices=(cpu cl)
# The scenes' canonical path: moments files record the scene's path, so two checkouts beside
# the same shared/ folder hash equal moments only if they name it alike.
shared="$(cd "$here/../shared/scenes" 2>/dev/null && pwd -P || echo "$here/../shared/scenes")"
size=()
case "$mode" in
  quick) size=(--resolution-scale 0.25 --spp 4) ;;
  own) size=(--resolution-scale 0.1) ;;
  full) ;;
  *) echo "pixel_hashes.sh: mode must be quick, own or full, not '$mode'" >&2; exit 2 ;;
esac
# shellcheck disable=SC2206
size+=(${RT_PIXEL_FLAGS:-})
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache"

render() {  # NAME SCENE FLAGS...
  local name="$1" scene="$2"
  shift 2
  for dev in "${devices[@]}"; do
    local out="$work/$dev/$name"
    mkdir -p "$out"
    if ! "$build/raytracer" "$scene" --device "$dev" --output-dir "$out" --moments --quiet \
      "${size[@]}" "$@" 2> "$out/stderr.txt"; then
      echo "$dev $name failed: $(head -c 200 "$out/stderr.txt" | head -1)"
      continue
    fi
    (cd "$out" && for f in $(ls | grep -v stderr.txt | sort); do
      echo "$dev $name $f $(sha256sum < "$f" | cut -c1-16)"
    done)
  done
}

while read -r name scene _ _ flags; do
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  if [ ! -f "$shared/$scene" ]; then echo "missing $name"; continue; fi
  # shellcheck disable=SC2086
  render "$name" "$shared/$scene" $flags
done < "$here/tests/course/course_scenes.txt"
render example "$here/scenes/example.xml"
[ -f "$shared/hw3/tap_water/xml/tap_0200.xml" ] && render tap_0200 "$shared/hw3/tap_water/xml/tap_0200.xml"
exit 0
