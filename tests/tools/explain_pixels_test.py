#!/usr/bin/env python3
"""Tests of tools/explain_ensemble.py and tools/explain_pixels.py.

usage: tests/tools/explain_pixels_test.py synthetic
       tests/tools/explain_pixels_test.py crop RAYTRACER SHARED_SCENES_DIR WORK_DIR
       tests/tools/explain_pixels_test.py model_pixel SHARED_SCENES_DIR

synthetic: the arithmetic on made-up inputs (float ulps, the perturbed radii, the order
of the members, each mechanism on a 4x3 image). crop: hw1 spheres rendered with six
members of the ensemble; every pixel of a crop around its green sphere where our image
differs from the course's must be attained by a member (rounding), with 100 or more such
pixels so that the assertion is not empty. model_pixel: hw1 spheres_mirror (413, 413),
which no member moves, is the course's value under tools/whitted_probe.py's float sphere
test and ours under its double one. Exits 77 (CTest's skip) when the course's
scene is missing.
"""
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)
import explain_ensemble as ens  # noqa: E402
import explain_pixels as exp  # noqa: E402


def check(condition, message):
    if not condition:
        sys.exit(f"FAIL: {message}")


def synthetic():
    check(ens.ulp32(1.0) == 2.0**-23, f"ulp32(1) = {ens.ulp32(1.0)}")
    check(ens.ulp32(289.0) == 2.0**-15, f"ulp32(289) = {ens.ulp32(289.0)}")
    check(ens.ulp32(-367.6) == 2.0**-15, f"ulp32(-367.6) = {ens.ulp32(-367.6)}")
    check(ens.ulp32(2.5) == 2.0**-22, f"ulp32(2.5) = {ens.ulp32(2.5)}")
    # A sphere 17 units from the eye: r^2 moves by k ulps of 289 (2^-15) exactly.
    scene = ET.fromstring(
        "<Scene><Cameras><Camera><Position>0 0 0</Position><NearDistance>1</NearDistance>"
        "</Camera></Cameras><VertexData>0 0 -17</VertexData><Objects><Sphere><Center>1</Center>"
        "<Radius>0.3</Radius></Sphere></Objects></Scene>")
    step = ens.edit_radii(-2)(scene)
    r = float(scene.findtext("Objects/Sphere/Radius"))
    check(step == 2.0**-15, f"r2 step {step}")
    check(abs((r * r - 0.09) / step + 2) < 1e-6, f"r^2 moved by {(r * r - 0.09) / step} ulps")
    # The camera at the origin moves by ulps of its film point (NearDistance 1: 2^-23).
    check(ens.edit_position(1, (1, -1, 1))(scene) == 2.0**-23, "position step")
    moved = [float(v) for v in scene.findtext("Cameras/Camera/Position").split()]
    check(moved == [2.0**-23, -(2.0**-23), 2.0**-23], f"moved camera {moved}")
    order = sorted(["r2+4", "r2-1", "gaze+1", "robust", "pos-2", "exact", "r2+2", "light+1",
                    "r2-0.5"], key=exp.rank)
    check(order == ["exact", "gaze+1", "pos-2", "light+1", "r2-0.5", "r2-1", "r2+2", "r2+4",
                    "robust"],
          f"member order {order}")
    # A 4x3 image, one pixel per mechanism (x, y): (0,0) attained by r2+1 and pos+1, which
    # names the camera family; (1,0) one level off 0.01 above a level: boundary; (2,0) our
    # value is the course's left neighbour: edge; (3,0) 40 levels off: unexplained.
    w, h = 4, 3
    course = bytearray([10] * (3 * w * h))
    course[0:3] = bytes([20, 20, 20])
    course[6:9] = bytes([90, 90, 90])
    base = bytearray(course)
    base[0:3] = bytes([21, 20, 20])
    base[3:6] = bytes([11, 10, 10])
    base[6:9] = bytes([10, 10, 10])
    base[9:12] = bytes([50, 10, 10])
    course[3:6] = bytes([10, 10, 10])
    radiance = tuple([float(base[3 * i + c]) + 0.5 for i in range(w * h)] for c in range(3))
    radiance[0][1] = 11.01
    members = {"pos+1": bytearray(course), "r2+1": bytearray(course), "gaze-1": bytearray(base)}
    members["pos+1"][9:12] = bytes([60, 10, 10])  # Changes (3,0) but not to the course's.
    rows = {(x, y): (mech, att) for x, y, _, mech, att in
            exp.explain(base, course, radiance, members, w, h, (0, 0, w, h))}
    check(sorted(rows) == [(0, 0), (1, 0), (2, 0), (3, 0)], f"differing pixels {sorted(rows)}")
    check(rows[(0, 0)] == ("rounding:camera", ["pos+1", "r2+1"]), f"(0,0): {rows[(0, 0)]}")
    check(rows[(1, 0)][0] == "rounding:camera", f"(1,0): {rows[(1, 0)]}")
    del members["pos+1"], members["r2+1"]
    rows = {(x, y): mech for x, y, _, mech, _ in
            exp.explain(base, course, radiance, members, w, h, (0, 0, w, h))}
    check(rows == {(0, 0): "unexplained", (1, 0): "boundary", (2, 0): "edge", (3, 0): "unexplained"},
          f"mechanisms without members: {rows}")
    # At (0,0) ours 21 and the course 20: the mirror value 22 20 20, attained by one member.
    members["gaze-1"][0:3] = bytes([22, 20, 20])
    rows = list(exp.explain(base, course, radiance, members, w, h, (0, 0, w, h)))
    check(exp.mirror_control(rows, base, course, members, w) == (1, 1), "mirror control")
    # At (3,0) ours 50, the course 10, a member 0: bracketed by r2+1.
    members["r2+1"] = bytearray(base)
    members["r2+1"][9:12] = bytes([0, 10, 10])
    rows = {(x, y): (mech, att) for x, y, _, mech, att in
            exp.explain(base, course, radiance, members, w, h, (0, 0, w, h))}
    check(rows[(3, 0)] == ("bracketed:sphere", ["(r2+1)"]), f"(3,0): {rows[(3, 0)]}")
    reach = exp.member_reach(base, course, bytearray(course), w, (0, 0, w, h))
    check(reach == (4, 4, 0), f"reach of a member equal to the course's image: {reach}")
    # The hit point member is our arithmetic; the independent model ranks after the
    # combined members, the conventions after everything.
    order = sorted(["facing", "model:f32_sphere", "exact&pos+1", "robust", "surface", "r2-1",
                    "cull"], key=exp.rank)
    check(order == ["surface", "r2-1", "exact&pos+1", "model:f32_sphere", "robust", "cull",
                    "facing"],
          f"member order with model and conventions {order}")
    # A model file (tools/whitted_probe.py --batch lines) sets only the pixels it lists.
    path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"explain_model_{os.getpid()}.txt")
    with open(path, "w") as f:
        f.write("3 0  model 10 10 10  course 10 10 10  ours 50 10 10  10.5 10.5 10.5  c course\n"
                "class c: model equals course: 1\n")
    model = exp.read_model(path, base, w)
    os.remove(path)
    check(model[9:12] == course[9:12] and model[:9] == base[:9] and model[12:] == base[12:],
          "model image")
    members = {"model:f32_sphere": model}
    rows = {(x, y): (mech, att) for x, y, _, mech, att in
            exp.explain(base, course, radiance, members, w, h, (0, 0, w, h))}
    check(rows[(3, 0)] == ("rounding:model", ["model:f32_sphere"]), f"(3,0): {rows[(3, 0)]}")
    print("synthetic: ok")


def crop(raytracer, shared, work):
    scene = os.path.join(shared, "hw1", "spheres.xml")
    course = os.path.join(shared, "hw1", "reference", "spheres.png")
    if not (os.path.exists(scene) and os.path.exists(course)):
        print(f"SKIP: {scene} or {course} is not present (../shared/scenes)")
        sys.exit(77)
    members = "r2+1,r2-1,r2+2,r2-2,gazeb-1,exact"
    subprocess.run([sys.executable, os.path.join(TOOLS, "explain_ensemble.py"), scene, work,
                    "--raytracer", raytracer, "--members", members, "--", "--cull-back-faces"],
                   check=True)
    out = subprocess.run([sys.executable, os.path.join(TOOLS, "explain_pixels.py"), work, course,
                          "--crop", *CROP, "--list-unexplained"],
                         check=True, capture_output=True, text=True).stdout
    print(out)
    first = out.split("\n")[0].split()
    differ, unexplained = int(first[3]), int(first[5])
    rounding = sum(int(line.split()[-1]) for line in out.split("\n")
                   if line.strip().startswith("rounding:"))
    check(differ >= 100, f"only {differ} differing pixels in the crop")
    check(rounding == differ and unexplained == 0,
          f"{differ - rounding} of {differ} differing pixels not attained by a member")
    print("crop: ok")


def model_pixel(shared):
    """hw1 spheres_mirror (413, 413), the one pixel of that image no member of the renderer's
    ensemble moves: ours 198 192 115, the course's 198 192 116. The independent tracer gives
    ours with its double-precision sphere test and the course's with the course's textbook
    test in float, whose normal (p - c) / r is not of unit length."""
    scene = os.path.join(shared, "hw1", "spheres_mirror.xml")
    course = os.path.join(shared, "hw1", "reference", "spheres_mirror.png")
    if not (os.path.exists(scene) and os.path.exists(course)):
        print(f"SKIP: {scene} or {course} is not present (../shared/scenes)")
        sys.exit(77)
    from classify_pixels import read_png
    w, _, image = read_png(course)
    i = 3 * (413 * w + 413)
    check(list(image[i : i + 3]) == [198, 192, 116], f"course pixel {list(image[i : i + 3])}")
    probe = [sys.executable, os.path.join(TOOLS, "whitted_probe.py"), scene, "413", "413",
             "--cull-back-faces", "--quiet"]
    values = {}
    for sphere in ("double", "f32_abc", "f32_shirley"):
        out = subprocess.run(probe + ["--set", f"sphere={sphere}"], check=True,
                             capture_output=True, text=True).stdout
        values[sphere] = out.split("8-bit")[1].split()
        print(f"sphere={sphere}: {out.strip()}")
    check(values["double"] == ["198", "192", "115"], f"double sphere test {values['double']}")
    check(values["f32_abc"] == values["f32_shirley"] == ["198", "192", "116"],
          f"float sphere tests {values['f32_abc']} {values['f32_shirley']}")
    print("model_pixel: ok")


CROP = ["260", "80", "460", "280"]  # The red sphere and the green one to its left.

if __name__ == "__main__":
    if sys.argv[1:2] == ["synthetic"]:
        synthetic()
    elif sys.argv[1:2] == ["crop"] and len(sys.argv) == 5:
        crop(*sys.argv[2:5])
    elif sys.argv[1:2] == ["model_pixel"] and len(sys.argv) == 3:
        model_pixel(sys.argv[2])
    else:
        sys.exit(__doc__)
