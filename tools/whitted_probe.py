#!/usr/bin/env python3
"""An independent Whitted tracer in double precision for single pixels of hw1 scenes.

usage: tools/whitted_probe.py SCENE.xml X Y [X Y ...] [--cull-back-faces] [--set NAME=VALUE ...]

Prints, for each pixel, the radiance and its parts: ambient, per light diffuse and
specular (with the shadow ray's verdict), and the mirror ray's radiance per bounce. It
reads the subset of the course's format that hw1 uses (spheres, triangles, meshes with
flat or smooth shading given by <Faces>, point lights, ambient light, mirrors) and exists
to find the course renderer's conventions by changing one at a time (--set, see CONVENTIONS
below) and comparing with the course's image (tools/classify_pixels.py lists the pixels).
"""
import argparse
import math
import struct
import sys
import xml.etree.ElementTree as ET

# Each convention: its default (this project's renderer) and what the alternatives mean.
CONVENTIONS = {
    "spec_needs_cos": 1,  # 1: no specular where n.l <= 0 (ours); 0: specular regardless.
    "cull": "camera",  # camera (ours, with --cull-back-faces), all rays, or none.
    "normals": "area",  # smooth-mesh vertex normals: area, unit (mean of unit face normals), angle.
    "normals_scope": "mesh",  # mesh (ours) or scene: vertices shared by meshes share normals.
    "dx": 0.5,  # sample position in the pixel
    "dy": 0.5,
    "shadow_eps_scale": 1.0,
    "max_depth": None,  # None: the file's MaxRecursionDepth (default 6 as ours)
    "depth_extra": 0,  # added to the depth limit (the course may count depth differently)
    "shadow_normal": "geometric",  # the shadow ray leaves along the geometric or shading normal
    "mirror_offset": "normal",  # the reflected ray leaves from p + eps n, or p + eps r (direction)
    "sphere": "double",  # double, or the textbook quadratic in float: f32_abc (b^2 - 4ac) or
    # f32_shirley ((d.oc)^2 - (d.d)(oc.oc - r^2)); the hit point o + t d and normal in float too.
    "camera_dir": "unit",  # unit (ours) or raw: s - e, unnormalized (matters for the float forms)
    "camera": "double",  # double, or f32: q = e - w dist + l u + t v, s = q + su u - sv v in float
}


def f32(x):
    """x rounded to the nearest float32 (exact emulation of one float operation)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def fdot(a, b):
    return f32(f32(f32(a[0] * b[0]) + f32(a[1] * b[1])) + f32(a[2] * b[2]))


def fsub(a, b):
    return tuple(f32(a[i] - b[i]) for i in range(3))


def sphere_f32(o, d, c, r, form):
    """The textbook sphere test evaluated in float: (t, p, n) or None."""
    o, d, c, r = tuple(map(f32, o)), tuple(map(f32, d)), tuple(map(f32, c)), f32(r)
    oc = fsub(o, c)
    a = fdot(d, d)
    if form == "f32_abc":
        b = f32(2 * fdot(d, oc))
        cc = f32(fdot(oc, oc) - f32(r * r))
        disc = f32(f32(b * b) - f32(f32(4 * a) * cc))
        if disc < 0:
            return None
        sq = f32(math.sqrt(disc))
        t = f32(f32(-b - sq) / f32(2 * a))
    else:
        b = fdot(d, oc)
        cc = f32(fdot(oc, oc) - f32(r * r))
        disc = f32(f32(b * b) - f32(a * cc))
        if disc < 0:
            return None
        sq = f32(math.sqrt(disc))
        t = f32(f32(-b - sq) / a)
    if t <= 0:
        return None
    p = tuple(f32(o[i] + f32(t * d[i])) for i in range(3))
    n = tuple(f32(v / r) for v in fsub(p, c))
    return t, p, n


def vec(s):
    return tuple(float(v) for v in s.split())


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def hadamard(a, b):
    return (a[0] * b[0], a[1] * b[1], a[2] * b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    length = math.sqrt(dot(a, a))
    return mul(a, 1.0 / length) if length > 0 else a


class Scene:
    def __init__(self, path, conv):
        root = ET.parse(path).getroot()
        self.conv = conv
        text = lambda tag, default=None: (root.findtext(tag) or default)
        self.background = vec(text("BackgroundColor", "0 0 0"))
        self.shadow_eps = float(text("ShadowRayEpsilon", "1e-3")) * conv["shadow_eps_scale"]
        self.max_depth = int(text("MaxRecursionDepth", "6"))
        if conv["max_depth"] is not None:
            self.max_depth = int(conv["max_depth"])
        self.max_depth += int(conv["depth_extra"])
        cam = root.find("Cameras/Camera")
        self.eye = vec(cam.findtext("Position"))
        gaze = norm(vec(cam.findtext("Gaze")))
        up = vec(cam.findtext("Up"))
        self.w = mul(gaze, -1)
        self.u = norm(cross(up, self.w))
        self.v = cross(self.w, self.u)
        self.l, self.r, self.b, self.t = vec(cam.findtext("NearPlane"))[:4]
        self.near = float(cam.findtext("NearDistance"))
        self.nx, self.ny = (int(v) for v in cam.findtext("ImageResolution").split())
        lights = root.find("Lights")
        self.ambient = vec(lights.findtext("AmbientLight", "0 0 0"))
        self.lights = [(vec(p.findtext("Position")), vec(p.findtext("Intensity")))
                       for p in lights.findall("PointLight")]
        self.materials = {}
        for m in root.find("Materials").findall("Material"):
            get = lambda tag, d="0 0 0": vec(m.findtext(tag, d))
            self.materials[m.get("id")] = dict(
                ka=get("AmbientReflectance"), kd=get("DiffuseReflectance"),
                ks=get("SpecularReflectance"), p=float(m.findtext("PhongExponent", "1")),
                km=get("MirrorReflectance") if m.get("type") == "mirror" else None)
        verts = vec(root.findtext("VertexData"))
        self.verts = [verts[i : i + 3] for i in range(0, len(verts), 3)]
        self.spheres, self.tris = [], []  # tris: (a, b, c, material, vertex ids, smooth)
        objects = root.find("Objects")
        for s in objects.findall("Sphere"):
            c = self.verts[int(s.findtext("Center")) - 1]
            self.spheres.append((c, float(s.findtext("Radius")), s.findtext("Material").strip()))
        for t in objects.findall("Triangle"):
            ids = [int(i) - 1 for i in t.findtext("Indices").split()]
            self.add_tri(ids, t.findtext("Material").strip(), False, 0)
        for k, mesh in enumerate(objects.findall("Mesh")):
            ids = [int(i) - 1 for i in mesh.findtext("Faces").split()]
            smooth = mesh.get("shadingMode") == "smooth"
            for i in range(0, len(ids), 3):
                self.add_tri(ids[i : i + 3], mesh.findtext("Material").strip(), smooth, k + 1)
        self.vertex_normals()

    def add_tri(self, ids, material, smooth, mesh):
        a, b, c = (self.verts[i] for i in ids)
        self.tris.append((a, b, c, material, ids, smooth, mesh))

    def vertex_normals(self):
        self.vn = {}
        for a, b, c, _, ids, smooth, mesh in self.tris:
            if not smooth:
                continue
            f = cross(sub(b, a), sub(c, a))
            pts = (a, b, c)
            for k, i in enumerate(ids):
                key = i if self.conv["normals_scope"] == "scene" else (mesh, i)
                if self.conv["normals"] == "unit":
                    contrib = norm(f)
                elif self.conv["normals"] == "angle":
                    e1 = norm(sub(pts[(k + 1) % 3], pts[k]))
                    e2 = norm(sub(pts[(k + 2) % 3], pts[k]))
                    contrib = mul(norm(f), math.acos(max(-1.0, min(1.0, dot(e1, e2)))))
                else:
                    contrib = f
                self.vn[key] = add(self.vn.get(key, (0.0, 0.0, 0.0)), contrib)

    def intersect(self, o, d, cull, tmax=math.inf):
        """Closest hit: (t, point, geometric normal, shading normal, material, what)."""
        best = None
        for k, (c, r, mat) in enumerate(self.spheres):
            if self.conv["sphere"] != "double":
                h = sphere_f32(o, d, c, r, self.conv["sphere"])
                if h and h[0] < tmax and (best is None or h[0] < best[0]):
                    best = (h[0], h[1], h[2], h[2], mat, f"sphere{k + 1}")
                continue
            oc = sub(o, c)
            a, b, cc = dot(d, d), 2 * dot(d, oc), dot(oc, oc) - r * r
            disc = b * b - 4 * a * cc
            if disc < 0:
                continue
            sq = math.sqrt(disc)
            for t in ((-b - sq) / (2 * a), (-b + sq) / (2 * a)):
                if 1e-9 < t < tmax and (best is None or t < best[0]):
                    p = add(o, mul(d, t))
                    n = norm(sub(p, c))
                    best = (t, p, n, n, mat, f"sphere{k + 1}")
                    break
        for k, (a, b, c, mat, ids, smooth, mesh) in enumerate(self.tris):
            e1, e2 = sub(b, a), sub(c, a)
            pv = cross(d, e2)
            det = dot(e1, pv)
            if det == 0 or (cull and det < 0):
                continue
            tv = sub(o, a)
            u = dot(tv, pv) / det
            if u < 0 or u > 1:
                continue
            qv = cross(tv, e1)
            v = dot(d, qv) / det
            if v < 0 or u + v > 1:
                continue
            t = dot(e2, qv) / det
            if 1e-9 < t < tmax and (best is None or t < best[0]):
                ng = norm(cross(e1, e2))
                n = ng
                if smooth:
                    keys = ids if self.conv["normals_scope"] == "scene" else [(mesh, i) for i in ids]
                    ns = [norm(self.vn[key]) for key in keys]
                    n = norm(add(add(mul(ns[0], 1 - u - v), mul(ns[1], u)), mul(ns[2], v)))
                best = (t, add(o, mul(d, t)), ng, n, mat, f"tri{k}")
        return best

    def near_edges(self, o, d, tmax, tol=1e-4):
        """Triangles whose edge the segment passes within tol (in barycentric units)."""
        out = []
        for k, (a, b, c, mat, ids, smooth, mesh) in enumerate(self.tris):
            e1, e2 = sub(b, a), sub(c, a)
            pv = cross(d, e2)
            det = dot(e1, pv)
            if det == 0:
                continue
            tv = sub(o, a)
            u = dot(tv, pv) / det
            qv = cross(tv, e1)
            v = dot(d, qv) / det
            t = dot(e2, qv) / det
            margin = min(u, v, 1 - u - v)
            if 0 < t < tmax and -tol < margin < tol:
                out.append(f"tri{k} margin {margin:.2e} t {t:.4f}")
        return out

    def camera_ray(self, x, y):
        if self.conv["camera"] == "f32":
            e, u, v, w = (tuple(map(f32, a)) for a in (self.eye, self.u, self.v, self.w))
            fm = lambda a, k: tuple(f32(c * f32(k)) for c in a)
            fa = lambda a, b: tuple(f32(a[i] + b[i]) for i in range(3))
            q = fa(fa(fa(e, fm(w, -self.near)), fm(u, self.l)), fm(v, self.t))
            su = f32(f32(f32(x + self.conv["dx"]) * f32(self.r - self.l)) / self.nx)
            sv = f32(f32(f32(y + self.conv["dy"]) * f32(self.t - self.b)) / self.ny)
            s = fa(fa(q, fm(u, su)), fm(v, -sv))
            d = fsub(s, e)
            if self.conv["camera_dir"] == "raw":
                return e, d
            length = f32(math.sqrt(fdot(d, d)))
            return e, tuple(f32(c / length) for c in d)
        su = (self.r - self.l) * (x + self.conv["dx"]) / self.nx
        sv = (self.t - self.b) * (y + self.conv["dy"]) / self.ny
        film = add(add(mul(self.u, self.l + su), mul(self.v, self.t - sv)), mul(self.w, -self.near))
        return self.eye, film if self.conv["camera_dir"] == "raw" else norm(film)

    def shade(self, o, d, depth, log, weight=(1.0, 1.0, 1.0)):
        cull = self.conv["cull"] == "all" or (self.conv["cull"] == "camera" and depth == 0)
        hit = self.intersect(o, d, cull)
        if hit is None:
            log.append(f"  depth {depth}: miss")
            return self.background if depth == 0 else (0.0, 0.0, 0.0)
        t, p, ng, n, mat_id, what = hit
        m = self.materials[mat_id]
        wo = mul(d, -1)
        color = hadamard(m["ka"], self.ambient)
        log.append(f"  depth {depth}: {what} t={t:.6f} p=({p[0]:.5f} {p[1]:.5f} {p[2]:.5f}) "
                   f"n=({n[0]:.5f} {n[1]:.5f} {n[2]:.5f}) ambient {fmt(mul3(color, weight))}")
        for k, (lp, intensity) in enumerate(self.lights):
            wi_raw = sub(lp, p)
            dist2 = dot(wi_raw, wi_raw)
            wi = norm(wi_raw)
            cos_i = dot(n, wi)
            off = n if self.conv["shadow_normal"] == "shading" else ng
            origin = add(p, mul(off, self.shadow_eps))
            seg = sub(lp, origin)
            blocker = self.intersect(origin, seg, self.conv["cull"] == "all", 1.0)
            e = mul(intensity, 1.0 / dist2)
            h = norm(add(wi, wo))
            cos_h = max(0.0, dot(n, h))
            diff = hadamard(m["kd"], mul(e, max(0.0, cos_i)))
            spec = hadamard(m["ks"], mul(e, cos_h ** m["p"] if cos_h > 0 else 0.0))
            if self.conv["spec_needs_cos"] and cos_i <= 0:
                spec = (0.0, 0.0, 0.0)
            shadowed = blocker is not None
            log.append(f"    light {k + 1}: cos_i={cos_i:.6f} cos_h={cos_h:.6f} diffuse {fmt(mul3(diff, weight))}"
                       f" specular {fmt(mul3(spec, weight))} {'SHADOWED by ' + blocker[5] + f' at {blocker[0]:.4f} facing ' + ('away' if dot(blocker[2], seg) > 0 else 'towards') if shadowed else 'lit'}")
            edges = self.near_edges(origin, seg, 1.0)
            if edges:
                log.append("      shadow ray near edges: " + "; ".join(edges))
            if not shadowed:
                color = add(color, add(diff, spec))
        if m["km"] is not None and depth < self.max_depth:
            r = sub(d, mul(n, 2 * dot(n, d)))
            r = norm(r)
            along = r if self.conv["mirror_offset"] == "direction" else ng
            origin = add(p, mul(along, self.shadow_eps))
            w2 = hadamard(weight, m["km"])
            color = add(color, hadamard(m["km"], self.shade(origin, r, depth + 1, log, w2)))
        return color


def mul3(a, b):
    return hadamard(a, b)


def fmt(c):
    return " ".join(f"{v:.4f}" for v in c)


def batch(scene, path):
    """For each listed pixel: does this model give the course's 8-bit value? And ours?"""
    counts = {}
    for line in open(path):
        f = line.split()
        if len(f) < 12 or not f[0].isdigit():
            continue
        x, y, ours, course, cls = int(f[0]), int(f[1]), f[2:5], f[5:8], f[11]
        o, d = scene.camera_ray(x, y)
        c = scene.shade(o, d, 0, [])
        mine = [str(int(min(255, max(0, v)))) for v in c]
        key = (cls, "course" if mine == course else "ours" if mine == ours else "neither")
        counts[key] = counts.get(key, 0) + 1
        print(f"{x} {y}  model {' '.join(mine)}  course {' '.join(course)}  ours {' '.join(ours)}"
              f"  {fmt(c)}  {cls} {key[1]}")
    for key in sorted(counts):
        print(f"class {key[0]}: model equals {key[1]}: {counts[key]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("pixels", nargs="+", type=int)
    parser.add_argument("--cull-back-faces", action="store_true")
    parser.add_argument("--set", action="append", default=[], help="convention NAME=VALUE")
    parser.add_argument("--quiet", action="store_true", help="only the radiance per pixel")
    parser.add_argument("--batch", help="pixels from classify_pixels.py --list: count matches")
    args = parser.parse_args()
    conv = dict(CONVENTIONS)
    if not args.cull_back_faces:
        conv["cull"] = "none"
    for s in args.set:
        name, value = s.split("=", 1)
        if name not in conv:
            sys.exit(f"unknown convention {name}; known: {', '.join(CONVENTIONS)}")
        conv[name] = type(CONVENTIONS[name])(value) if CONVENTIONS[name] is not None else value
    scene = Scene(args.scene, conv)
    if args.batch:
        return batch(scene, args.batch)
    for x, y in zip(args.pixels[0::2], args.pixels[1::2]):
        o, d = scene.camera_ray(x, y)
        log = []
        c = scene.shade(o, d, 0, log)
        print(f"{x} {y}  radiance {fmt(c)}  8-bit {' '.join(str(int(min(255, max(0, v)))) for v in c)}")
        if not args.quiet:
            print("\n".join(log))


if __name__ == "__main__":
    main()
