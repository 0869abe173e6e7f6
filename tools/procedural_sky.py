#!/usr/bin/env python3
"""Writes a procedural lat-long sky as a Radiance RGBE file (.hdr), for the README's figure
of environment lights (docs/environment_light.xml): a blue sky brightening towards the
horizon, a small sun of high radiance, and a chequered ground. The mapping is the course's
(hw5/SPEC.txt): u = (1 + atan2(x, -z) / pi) / 2, v = acos(y) / pi, +y up.

usage: tools/procedural_sky.py OUT.hdr [WIDTH]"""
import math
import sys


def radiance(x, y, z):
    sun = (0.60, 0.35, 0.70)
    n = math.sqrt(sum(c * c for c in sun))
    if (x * sun[0] + y * sun[1] + z * sun[2]) / n > math.cos(math.radians(2.5)):
        return (200000.0, 180000.0, 150000.0)
    if y >= 0:
        t = 1.0 - y
        return (40 + 90 * t, 70 + 80 * t, 140 + 40 * t)
    # The ground: a chequerboard on the plane one unit below, fading with distance.
    px, pz = x / -y, z / -y
    light = (int(math.floor(px)) + int(math.floor(pz))) % 2 == 0
    fade = 1.0 / (1.0 + 0.02 * (px * px + pz * pz))
    g = (70 if light else 35) * fade + 20 * (1 - fade)
    return (g * 1.1, g, g * 0.85)


def rgbe(c):
    v = max(c)
    if v < 1e-32:
        return bytes(4)
    m, e = math.frexp(v)
    s = m * 256.0 / v
    return bytes([int(c[0] * s), int(c[1] * s), int(c[2] * s), e + 128])


def main():
    out = sys.argv[1]
    w = int(sys.argv[2]) if len(sys.argv) > 2 else 512
    h = w // 2
    rows = []
    for j in range(h):
        theta = math.pi * (j + 0.5) / h
        for i in range(w):
            phi = 2 * math.pi * ((i + 0.5) / w - 0.5)
            d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
            rows.append(rgbe(radiance(*d)))
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(("-Y %d +X %d\n" % (h, w)).encode())
        f.write(b"".join(rows))


if __name__ == "__main__":
    main()
