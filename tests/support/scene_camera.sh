# Sourced by the scene tests (cl_vs_cpu.sh, convert_roundtrip.sh).

# Exits with 77 (CTest's skip) when the course's scene file is not there.
skip_unless_present() {
  if [ ! -f "$1" ]; then
    echo "SKIP: $1 is not present (the course's scenes live in ../shared/scenes)"
    exit 77
  fi
}

# For the camera a test
# renders (--camera N among the raytracer flags, else the first), sets `camera`, `res`
# (width height), `spp` (its NumSamples, 1 when absent) and `scale`, the
# --resolution-scale that gives about 4096 pixels of the same view.
# usage: scene_camera SCENE.xml [raytracer flags...]
scene_camera() {
  local file="$1" i
  shift
  local args=("$@")
  camera=0
  for ((i = 0; i < ${#args[@]}; ++i)); do
    [ "${args[$i]}" = "--camera" ] && camera="${args[$((i + 1))]}"
  done
  res=($(grep -o '<ImageResolution>[^<]*' "$file" | sed -n "$((camera + 1))p" | cut -d'>' -f2))
  spp=$(grep -o '<NumSamples>[^<]*' "$file" | sed -n "$((camera + 1))p" | cut -d'>' -f2)
  spp=${spp:-1}
  scale=$(awk -v w="${res[0]}" -v h="${res[1]}" 'BEGIN { s = sqrt(4096 / (w * h));
    printf "%.6f", s < 1 ? s : 1 }')
}
