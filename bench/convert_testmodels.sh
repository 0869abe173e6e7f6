#!/bin/bash
# How many models of Debian's assimp-testmodels (/usr/share/assimp/models) rtconvert imports
# and raytracer then renders without error, per format, and the failures with their one-line
# reason. Not a test: the collection holds models Assimp itself cannot read, on purpose.
# usage: bench/convert_testmodels.sh [BUILD_DIR] [MODELS_DIR]  (needs assimp-testmodels)
set -uo pipefail
build="$(cd "${1:-build}" && pwd)"
models="${2:-/usr/share/assimp/models}"
[ -d "$models" ] || { echo "no $models: apt-get install assimp-testmodels"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The extensions Assimp reads (as `assimp listext` prints them); .xml is left out (mostly
# Ogre and Irrlicht companions, not models) and so are textures, shaders and buffers.
exts="3d 3ds 3mf ac ac3d acc amf ase ask assbin b3d blend bsp bvh cob csm dae dxf enff fbx glb
gltf hmp ifc ifczip iqm irr irrmesh lwo lws lxo md2 md3 md5anim md5camera md5mesh mdc mdl mesh
mot ms3d ndo nff obj off ogex pk3 ply pmx prj q3o q3s raw scn sib smd step stl stp ter uc vta x
x3d x3db xgl zae zgl"
declare -A total imported rendered
failures=()
while IFS= read -r -d '' f; do
  ext="${f##*.}"
  ext="${ext,,}"
  [[ " ${exts//$'\n'/ } " == *" $ext "* ]] || continue
  total[$ext]=$((${total[$ext]:-0} + 1))
  rel="${f#"$models"/}"
  rm -rf "$work"/* && mkdir -p "$work/out"
  if ! timeout 60 "$build/rtconvert" "$f" "$work/scene.xml" --width 64 --quiet 2> "$work/err.txt"; then
    failures+=("$ext import  $rel: $(tail -1 "$work/err.txt" | cut -c1-160)")
    continue
  fi
  imported[$ext]=$((${imported[$ext]:-0} + 1))
  if ! timeout 120 "$build/raytracer" "$work/scene.xml" --device cpu --threads 1 --spp 1 --quiet \
      --output-dir "$work/out" 2> "$work/err.txt"; then
    failures+=("$ext render  $rel: $(tail -1 "$work/err.txt" | cut -c1-160)")
    continue
  fi
  rendered[$ext]=$((${rendered[$ext]:-0} + 1))
done < <(find "$models" -type f -print0 | sort -z)

printf "| format | models | imported | rendered |\n|---|---|---|---|\n"
all=0 imp=0 ren=0
for ext in $(printf "%s\n" "${!total[@]}" | sort); do
  printf "| %s | %d | %d | %d |\n" "$ext" "${total[$ext]}" "${imported[$ext]:-0}" "${rendered[$ext]:-0}"
  all=$((all + total[$ext])) imp=$((imp + ${imported[$ext]:-0})) ren=$((ren + ${rendered[$ext]:-0}))
done
printf "| all | %d | %d | %d |\n\nFailures (format, stage, file: reason):\n" $all $imp $ren
printf "%s\n" "${failures[@]}"
