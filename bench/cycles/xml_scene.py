# The parts of a CENG795 scene file that bench/cycles/scene_to_blender.py maps to Cycles:
# vertex data, transformations, BRDFs, materials and PLY meshes, read with the standard
# library and mathutils (Blender's), so that the Blender script holds only the mapping.
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET

from mathutils import Matrix, Vector


def fail(msg):
    print("scene_to_blender: " + msg, file=sys.stderr)
    sys.exit(1)


def floats(text):
    return [float(v) for v in (text or "").split()]


def read_ply(path):
    """Vertices and triangles of a PLY file (ascii or binary little endian, fans split)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if end < 0:
        fail(path + ": no end_header")
    header = data[:end].decode("ascii", "replace").split("\n")
    body = data[data.index(b"\n", end) + 1:]
    fmt, elements = "ascii", []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append([w[1], int(w[2]), []])
        elif w[0] == "property":
            elements[-1][2].append(w[1:])
    sizes = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I",
             "uint32": "I", "float": "f", "float32": "f", "double": "d", "float64": "d"}
    order = "<" if fmt == "binary_little_endian" else ">"
    tokens = body.split() if fmt == "ascii" else None
    pos, tok = 0, 0
    verts, tris = [], []

    def take(t):
        nonlocal pos, tok
        if tokens is not None:
            tok += 1
            return float(tokens[tok - 1])
        c = order + sizes[t]
        v = struct.unpack_from(c, body, pos)[0]
        pos += struct.calcsize(c)
        return v

    for name, count, props in elements:
        for _ in range(count):
            vals = {}
            for p in props:
                if p[0] == "list":
                    n = int(take(p[1]))
                    vals[p[3]] = [int(take(p[2])) for _ in range(n)]
                else:
                    vals[p[1]] = take(p[0])
            if name == "vertex":
                verts.append((vals["x"], vals["y"], vals["z"]))
            elif name == "face":
                idx = vals.get("vertex_indices", vals.get("vertex_index", []))
                for k in range(1, len(idx) - 1):
                    tris.append((idx[0], idx[k], idx[k + 1]))
    return verts, tris


class Scene:
    def __init__(self, path):
        self.path = path
        self.dir = os.path.dirname(os.path.abspath(path))
        self.root = ET.parse(path).getroot()
        r = self.root
        self.depth = int((r.findtext("MaxRecursionDepth") or "5").strip())
        self.vertices = self.triples(r.findtext("VertexData"))
        self.transforms = {}
        t = r.find("Transformations")
        for e in (list(t) if t is not None else []):
            key = {"Translation": "t", "Scaling": "s", "Rotation": "r"}.get(e.tag)
            if key:
                self.transforms[key + e.get("id")] = floats(e.text)
        self.brdfs = {}
        b = r.find("BRDFs")
        for e in (list(b) if b is not None else []):
            self.brdfs[e.get("id")] = (e.tag, e.get("normalized") == "true",
                                       float((e.findtext("Exponent") or "1").strip()))
        self.materials = {m.get("id"): m for m in r.iter("Material") if m.get("id")}

    @staticmethod
    def triples(text):
        v = floats(text)
        return [tuple(v[i:i + 3]) for i in range(0, len(v) - 2, 3)]

    def matrix(self, obj):
        m = Matrix.Identity(4)
        for word in (obj.findtext("Transformations") or "").split():
            v = self.transforms.get(word)
            if v is None:
                fail("%s: Transformations: unknown id %s" % (self.path, word))
            if word[0] == "t":
                step = Matrix.Translation(Vector(v))
            elif word[0] == "s":
                step = Matrix.Diagonal(Vector((v[0], v[1], v[2], 1.0)))
            else:
                step = Matrix.Rotation(math.radians(v[0]), 4, Vector(v[1:4]))
            m = step @ m  # Each transformation applies after the ones listed before it.
        return m
