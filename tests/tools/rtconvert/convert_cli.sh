#!/bin/bash
# rtconvert on a small OBJ + MTL written here (no test-model package needed): the material
# table (Blinn-Phong, mirror, glass), an emissive quad becoming an area light, a default
# camera, a render of the result; and bad input: one line naming the file, status 1, no
# output file left behind.
# usage: convert_cli.sh RTCONVERT RAYTRACER WORKDIR
set -uo pipefail
conv="$1" rt="$2" work="$3"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

cat > box.mtl <<'MTL'
newmtl red
Kd 0.8 0.2 0.2
Ks 0.5 0.5 0.5
Ns 40
newmtl chrome
Kd 0 0 0
Ks 0.9 0.9 0.9
illum 3
newmtl glass
Kd 0 0 0
d 0.2
Ni 1.45
newmtl lamp
Kd 0 0 0
Ke 1 1 1
MTL
cat > box.obj <<'OBJ'
mtllib box.mtl
v -2 0 -2
v 2 0 -2
v 2 0 2
v -2 0 2
v -0.5 2 -0.5
v 0.5 2 -0.5
v 0.5 2 0.5
v -0.5 2 0.5
v -1 0.5 0
v 0 1.5 0
v 1 0.5 0
usemtl red
f 1 4 3 2
usemtl lamp
f 5 6 7 8
usemtl chrome
f 9 11 10
usemtl glass
f 9 10 11
OBJ
"$conv" box.obj box.xml 2> warnings.txt || fail "import of box.obj: $(cat warnings.txt)"
cat warnings.txt
grep -q 'type="mirror"' box.xml || fail "illum 3 did not become a mirror"
grep -q 'type="dielectric"' box.xml || fail "d 0.2 did not become a dielectric"
grep -q '<RefractionIndex>1.45' box.xml || fail "Ni 1.45 was not kept"
grep -q '<PhongExponent>40</PhongExponent>' box.xml || fail "Ns 40 was not kept"
grep -A4 '<AreaLight' box.xml | grep -q '<Intensity>255 255 255' ||
  fail "the emissive quad did not become an area light of radiance 255"
grep -q 'no camera: a default one' warnings.txt || fail "no warning for the default camera"
grep -q 'partial transparency' warnings.txt || fail "no warning for d 0.2"
[ "$(grep -c '<Camera ' box.xml)" = 1 ] || fail "expected one default camera"
"$rt" box.xml --device cpu --threads 1 --resolution-scale 0.1 --quiet || fail "render of box.xml"
[ -f box.png ] || fail "no box.png (renders are named after the imported file)"

# Export the imported scene to every format; the glTF goes back to XML.
for out in box.glb box.obj2.obj box.pbrt; do
  "$conv" box.xml "$out" --quiet || fail "export to $out"
done
grep -q 'AreaLightSource "diffuse"' box.pbrt || fail "pbrt: no area light"
"$conv" box.glb again.xml --quiet || fail "import of box.glb"
cmp -s <(grep -v plyFile box.xml) <(grep -v plyFile again.xml) ||
  fail "box.xml -> box.glb -> again.xml changed the scene"
# Read as another tool's glTF: the camera comes from glTF's own camera node, the area
# light from its emissive quad (KHR_materials_emissive_strength).
"$conv" box.glb native.xml --no-extras 2> native.txt || fail "import of box.glb --no-extras"
grep -q 'no camera' native.txt && fail "--no-extras: the glTF camera was not read"
grep -q 'no light' native.txt && fail "--no-extras: the area light was not read"
grep -A4 '<AreaLight' native.xml | grep -q '<Intensity>255 255 255' ||
  fail "--no-extras: the emissive quad did not come back as an area light of radiance 255"
grep -A5 '<Camera ' native.xml | grep -q '<NearPlane>-0.48529' ||
  fail "--no-extras: the camera's field of view changed"

expect_error() {  # WHAT OUTPUT ARGS...
  local what="$1" output="$2"
  shift 2
  "$conv" "$@" > out.txt 2> err.txt
  local rc=$?
  [ $rc -eq 1 ] || fail "$what: status $rc, expected 1"
  [ "$(wc -l < err.txt)" = 1 ] || fail "$what: expected one line, got: $(cat err.txt)"
  grep -q "$what" err.txt || fail "expected '$what' in: $(cat err.txt)"
  [ ! -e "$output" ] || fail "$what: $output left behind"
  echo "ok: $(cat err.txt)"
}
expect_error "missing.glb" o1.xml missing.glb o1.xml
head -c 300 /dev/urandom > junk.glb
expect_error "junk.glb" o2.xml junk.glb o2.xml
expect_error "o3.stl" o3.stl box.xml o3.stl
expect_error "an import writes course XML" o4.glb box.obj o4.glb
printf 'v 0 0 0\nv 1 0 0\nl 1 2\n' > lines.obj
expect_error "no triangle geometry" o5.xml lines.obj o5.xml
"$conv" > /dev/null 2>&1
[ $? -eq 2 ] || fail "no arguments: expected status 2"
echo PASS
