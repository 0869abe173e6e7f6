#!/usr/bin/env python3
"""Renders a course scene several times, each perturbed by about float's own rounding.

usage: tools/explain_ensemble.py SCENE.xml OUTDIR [--raytracer build/raytracer]
                                 [--members NAME,...] [--list] [-- RAYTRACER FLAGS...]

Each member of the ensemble is a copy of SCENE.xml with one kind of quantity nudged by the
size of the rounding a float renderer applies to it, or our renderer run with one
arithmetic option changed; every member is rendered with `--device cpu --moments` and the
flags after `--` (the reference test's, e.g. --cull-back-faces). OUTDIR/base holds the
unperturbed render and OUTDIR/members.tsv names every member, what it changes and by how
much; tools/explain_pixels.py then asks, for each pixel where our image differs from the
course's, whether some member attains the course's value. A member that does shows that
the pixel's value is decided by rounding of that size: the two renderers agree on the
scene and differ in their last bits.

The members (an ulp is the spacing of float32 at the quantity's magnitude):
  pos±k      the camera Position, every component moved by k ulps (+ + +; posb, posc,
             posd: + - +, + + -, + - -) of the film point's largest coordinate, max(|Position|, NearDistance),
             the magnitude at which the course's float camera rounds s - e: the world
             moves by that much relative to the camera, and the film point is rounded
             afresh
  gaze±1     the Gaze moved likewise by one ulp of its largest component (gazeb, c, d)
  near±1     NearDistance moved by one ulp
  light±1    every point light's Position moved by one ulp of max(its largest coordinate,
             the camera's), the magnitude of the shadow ray's L - p for points in view
             (lightb, c, d: the other directions)
  eps±k      ShadowRayEpsilon moved by k = 1, 2 ulps of that same scale: the course adds
             it to points of about that magnitude, whose float spacing rounds the offset
             (grass_desert: 1e-3 ± 3.05e-5; the spheres: 1e-3 ± 9.5e-7)
  r2±k       every sphere's radius changed so that r^2 moves by k = 1/4 to 4 ulps of
             |centre - eye|^2: the textbook quadratic's discriminant (d.oc)^2 - (oc.oc -
             r^2) subtracts two terms of that size after about ten roundings of terms of
             that size (at most half an ulp each; 4 ulps is within that bound), so its
             error is that of an r^2 changed by that much, and the hit lies on the sphere
             of that radius, where the course's float quadratic puts it
  exact      --camera-rays exact: the camera ray formed relative to the camera, without
             the course's world-space float rounding of its direction
  double     --precision double: the whole renderer's arithmetic in double
  world      --frame world: the scene rounded to float in the file's coordinates, as the
             course holds it, not in the camera's frame (meshes keep their own frames)
  surface    --hit-point surface: the hit point rebuilt from the primitive (barycentrics,
             the unit sphere) instead of formed as origin + t * direction, as the course's
             renderer and our default form it (whose rounding grows with the distance
             travelled)
  A&B        members A and B at once (double or exact with pos±1 or light±1): the course's
             image carries all its roundings together
  facing, geometric, cull
             conventions, not roundings (--reflection-offset facing, --shadow-offset
             geometric, --cull-back-faces where the flags do not cull already): they change
             every pixel of a kind, so they only say the course may treat a pixel otherwise
  robust     --ray-offset robust: secondary rays start 8 ulps of the surface point's
             coordinates further out (larger than rounding where a point's coordinates
             are large: grass_desert's ground, scaled by 1e4, gets 8e-3; reported apart)
"""
import argparse
import math
import os
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def ulp32(x):
    """The spacing of float32 at |x| (the distance to the next float away from zero)."""
    x = abs(f32(x))
    if x == 0.0:
        return 2.0**-149
    bits = struct.unpack("I", struct.pack("f", x))[0]
    return struct.unpack("f", struct.pack("I", bits + 1))[0] - x


def numbers(text):
    return [float(v) for v in text.split()]


def fmt(values):
    # repr of a double round-trips exactly; the renderer reads the file's numbers as doubles.
    return " ".join(repr(v) for v in values)


def nudge_vector(elem, k, pattern, scale=0.0):
    """Moves each component by k ulps (float32) of max(the largest component, scale)."""
    v = numbers(elem.text)
    step = ulp32(max(max(abs(c) for c in v), scale))
    elem.text = fmt([f32(c) + s * k * step for c, s in zip(v, pattern)])
    return step


def vertices(root):
    data = numbers(root.findtext("VertexData") or "")
    return [data[i : i + 3] for i in range(0, len(data), 3)]


def camera(root):
    return root.find("Cameras/Camera")


def edit_position(k, pattern):
    """Moves the camera by k ulps of its film point's largest coordinate, which the course
    rounds when it forms s - e: max(|Position|, NearDistance) (a camera at the origin still
    has a film point 1-10 units out)."""
    def edit(root):
        cam = camera(root)
        return nudge_vector(cam.find("Position"), k, pattern, float(cam.findtext("NearDistance")))
    return edit


def edit_gaze(k, pattern):
    def edit(root):
        return nudge_vector(camera(root).find("Gaze"), k, pattern)
    return edit


def edit_near(k):
    def edit(root):
        e = camera(root).find("NearDistance")
        d = float(e.text)
        e.text = repr(f32(d) + k * ulp32(d))
        return ulp32(d)
    return edit


def edit_epsilon(k):
    """ShadowRayEpsilon moved by k ulps of the film point's scale (as edit_position): the
    course adds it to points of about that magnitude, whose float spacing rounds it."""
    def edit(root):
        cam = camera(root)
        scale = max(max(abs(c) for c in numbers(cam.findtext("Position"))),
                    float(cam.findtext("NearDistance")))
        e = root.find("ShadowRayEpsilon")
        if e is None:
            e = ET.SubElement(root, "ShadowRayEpsilon")
            e.text = "1e-3"
        e.text = repr(float(e.text) + k * ulp32(scale))
        return ulp32(scale)
    return edit


def edit_lights(k, pattern):
    """Moves every point light by k ulps of max(its largest coordinate, the camera's): the
    shadow ray's direction L - p is rounded at that magnitude for the points in view."""
    def edit(root):
        eye = max(abs(c) for c in numbers(camera(root).findtext("Position")))
        steps = [nudge_vector(p.find("Position"), k, pattern, eye)
                 for p in root.findall("Lights/PointLight")]
        return max(steps) if steps else None
    return edit


def edit_radii(k):
    """r^2 moved by k ulps of |centre - eye|^2 (spheres indexed into VertexData)."""
    def edit(root):
        verts, eye = vertices(root), numbers(camera(root).findtext("Position"))
        steps = []
        for s in root.findall("Objects/Sphere"):
            c = verts[int(s.findtext("Center")) - 1]
            r = float(s.findtext("Radius"))
            step = ulp32(sum((a - b) ** 2 for a, b in zip(c, eye)))
            s.find("Radius").text = repr(math.sqrt(r * r + k * step))
            steps.append(step)
        return max(steps) if steps else None
    return edit


# Other directions, each a different draw of the film point's rounding: b (+ - +),
# c (+ + -), d (+ - -); the letter-less members move along (+ + +).
PATTERNS = {"": (1, 1, 1), "b": (1, -1, 1), "c": (1, 1, -1), "d": (1, -1, -1)}


def signs(k, pattern):
    return ", ".join(f"{k * p:+d} {axis}" for p, axis in zip(pattern, "xyz"))


# name: (what it changes, XML edit or None, extra flags)
MEMBERS = {}
for k in (1, -1, 2, -2):
    MEMBERS[f"pos{k:+d}"] = (f"camera Position ulps {signs(k, (1, 1, 1))}",
                             edit_position(k, (1, 1, 1)), [])
for k in (1, -1):
    for letter, pattern in PATTERNS.items():
        if letter:
            MEMBERS[f"pos{letter}{k:+d}"] = (f"camera Position ulps {signs(k, pattern)}",
                                             edit_position(k, pattern), [])
    for letter, pattern in PATTERNS.items():
        MEMBERS[f"gaze{letter}{k:+d}"] = (f"Gaze ulps {signs(k, pattern)}", edit_gaze(k, pattern), [])
    MEMBERS[f"near{k:+d}"] = (f"NearDistance {k:+d} ulp", edit_near(k), [])
    for letter, pattern in PATTERNS.items():
        MEMBERS[f"light{letter}{k:+d}"] = (f"point lights' Position ulps {signs(k, pattern)}",
                                           edit_lights(k, pattern), [])
for k in (1, -1, 2, -2):
    MEMBERS[f"eps{k:+d}"] = (f"ShadowRayEpsilon {k:+d} ulp of the film point's scale",
                             edit_epsilon(k), [])
for k in (0.25, -0.25, 0.5, -0.5, 0.75, -0.75, 1, -1, 1.5, -1.5, 2, -2, 3, -3, 4, -4):
    MEMBERS[f"r2{k:+g}"] = (f"sphere r^2 {k:+g} ulp of |centre - eye|^2", edit_radii(k), [])
MEMBERS["exact"] = ("--camera-rays exact (no world-space float rounding of the camera ray)", None,
                    ["--camera-rays", "exact"])
MEMBERS["double"] = ("--precision double (our arithmetic in double)", None, ["--precision", "double"])
MEMBERS["world"] = ("--frame world (the scene rounded to float in the file's coordinates, as the "
                    "course holds it, instead of the camera's frame)", None, ["--frame", "world"])
MEMBERS["surface"] = ("--hit-point surface (the hit point rebuilt from the primitive, not origin + "
                      "t * direction as the course and our default form it)", None,
                      ["--hit-point", "surface"])
# Conventions, not roundings: each changes how the renderer treats every pixel of a kind,
# so a pixel only they attain says the course may decide that pixel differently, not that
# rounding does (explain_pixels.py's family convention, reported apart).
MEMBERS["facing"] = ("--reflection-offset facing (a mirror seen from behind reflects from the "
                     "viewer's side)", None, ["--reflection-offset", "facing"])
MEMBERS["geometric"] = ("--shadow-offset geometric (shadow rays leave along the triangle's "
                        "normal)", None, ["--shadow-offset", "geometric"])
MEMBERS["cull"] = ("--cull-back-faces (camera and reflected rays ignore triangles facing away)",
                   None, ["--cull-back-faces"])
MEMBERS["robust"] = ("--ray-offset robust (+8 ulps of the point's coordinates on the offset)", None,
                     ["--ray-offset", "robust"])


def combine(*names):
    """A member that applies several members at once: the course's image carries all its
    roundings together, and one member moves only one of ours."""
    edits = [MEMBERS[n][1] for n in names if MEMBERS[n][1] is not None]

    def edit(root):
        sizes = [e(root) for e in edits]
        return max((x for x in sizes if x is not None), default=None)
    return (" and ".join(MEMBERS[n][0] for n in names), edit if edits else None,
            [f for n in names for f in MEMBERS[n][2]])


for first in ("double", "exact"):
    for second in ("pos+1", "pos-1", "light+1", "light-1"):
        MEMBERS[f"{first}&{second}"] = combine(first, second)


def applicable(name, root, extra=()):
    if name == "cull" and "--cull-back-faces" in extra:
        return False
    if "&" in name:
        return all(applicable(n, root, extra) for n in name.split("&"))
    if name.startswith("r2"):
        return root.find("Objects/Sphere") is not None
    if name.startswith("light"):
        return root.find("Lights/PointLight") is not None
    return True


def scene_copy(scene, root, directory):
    """Writes the edited scene beside links to every file of the original's directory."""
    os.makedirs(directory, exist_ok=True)
    source = os.path.dirname(os.path.abspath(scene))
    for entry in os.listdir(source):
        link = os.path.join(directory, entry)
        if not os.path.lexists(link) and entry != os.path.basename(scene):
            os.symlink(os.path.join(source, entry), link)
    path = os.path.join(directory, "perturbed_" + os.path.basename(scene))
    ET.ElementTree(root).write(path)
    return path


def image_name(root):
    return camera(root).findtext("ImageName").strip()


def render(raytracer, scene, directory, flags):
    os.makedirs(directory, exist_ok=True)
    cmd = [raytracer, scene, "--device", "cpu", "--moments", "--quiet", "--output-dir", directory]
    subprocess.run(cmd + flags, check=True)


def main():
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1 :] if "--" in argv else []
    argv = argv[: argv.index("--")] if "--" in argv else argv
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("outdir")
    parser.add_argument("--raytracer", default="build/raytracer")
    parser.add_argument("--members", default=",".join(MEMBERS), help="comma-separated names")
    args = parser.parse_args(argv)
    names = [n for n in args.members.split(",") if n]
    unknown = [n for n in names if n not in MEMBERS]
    if unknown:
        sys.exit(f"unknown member {unknown[0]}; known: {', '.join(MEMBERS)}")
    original = ET.parse(args.scene).getroot()
    name = image_name(original)
    render(args.raytracer, args.scene, os.path.join(args.outdir, "base"), extra)
    rows = [("base", "unperturbed", "", os.path.join("base", name))]
    for member in names:
        what, edit, flags = MEMBERS[member]
        root = ET.parse(args.scene).getroot()
        if not applicable(member, root, extra):
            continue
        directory = os.path.join(args.outdir, member)
        scene, step = args.scene, ""
        if edit is not None:
            size = edit(root)
            step = f"{size:.3g}" if size is not None else ""
            scene = scene_copy(args.scene, root, directory)
        render(args.raytracer, scene, directory, extra + flags)
        rows.append((member, what, step, os.path.join(member, name)))
        print(f"{member}: {what} (1 ulp = {step or '-'})", file=sys.stderr)
    # Members rendered before into the same OUTDIR stay listed unless rendered again.
    table = os.path.join(args.outdir, "members.tsv")
    done = {row[0] for row in rows}
    if os.path.exists(table):
        with open(table) as f:
            old = [line.rstrip("\n").split("\t") for line in f if not line.startswith("#")]
        rows += [tuple(row) for row in old if row[0] not in done and row[0] in MEMBERS]
    with open(table, "w") as f:
        f.write("# member\twhat it changes\tone ulp of the quantity\timage\n")
        for row in rows:
            f.write("\t".join(row) + "\n")


if __name__ == "__main__":
    main()
