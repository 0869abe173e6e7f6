#!/usr/bin/env python3
"""Classifies the pixels where our render differs from the course's image.

usage: tools/classify_pixels.py OURS.png COURSE.png [--moments OURS.moments.exr]
                                [--list [CLASSES]] [--near A] [--wide B]

OURS.png is a one-sample render of a deterministic course scene rendered with `--moments`
(its moment file defaults to OURS.moments.exr beside it); COURSE.png is the course's
official image of the same camera. A pixel differs when any channel differs. Each
differing pixel gets the first class that fits:
  a   one level off in every differing channel, and our unclamped radiance of each
      differing channel lies within A (default 1e-3) of a whole level: the last bits of
      either renderer's float arithmetic decide the side of the truncation;
  a'  the same within B (default 0.05) of a whole level;
  b   our 8-bit value occurs, within one level in every channel, at one of the eight
      neighbouring pixels of the course's image (an edge displaced by under a pixel);
  c   the rest.
Prints one table line "differ a a' b c" (the README's Figures table) and, with --list, one
line per differing pixel of the given classes (default all; e.g. --list c or --list "a' c"):
x y, our RGB, the course's RGB, our radiance RGB, class. Only the Python standard library
is used: the PNG (8-bit gray/RGB/RGBA, not interlaced) and the OpenEXR moment file (scanline,
uncompressed or ZIP/ZIPS, as src/io/moments.cpp writes it) are decoded here.
"""
import argparse
import itertools
import struct
import sys
import zlib


def read_png(path):
    """Returns (width, height, rows of RGB byte triples flattened) of an 8-bit PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG file")
    pos, idat, header = 8, [], None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind, body = data[pos + 4 : pos + 8], data[pos + 8 : pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    width, height, depth, color, _, _, interlace = header
    channels = {0: 1, 2: 3, 6: 4}.get(color)
    if depth != 8 or channels is None or interlace:
        sys.exit(f"{path}: only 8-bit gray, RGB or RGBA non-interlaced PNGs are read")
    raw, stride = zlib.decompress(b"".join(idat)), width * channels
    out, prev = bytearray(), bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, upleft = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + ((left + up) >> 1)) & 255
            elif kind == 4:
                p = left + up - upleft
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upleft)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else upleft)
                line[i] = (line[i] + pred) & 255
        prev = line
        if channels == 3:
            out += line
        else:
            for x in range(width):
                px = line[x * channels : (x + 1) * channels]
                out += bytes((px[0], px[0], px[0])) if channels == 1 else px[:3]
    return width, height, out


def read_exr_channels(path, wanted):
    """Returns (width, height, {name: list of floats}) for the wanted FLOAT channels."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"\x76\x2f\x31\x01":
        sys.exit(f"{path}: not an OpenEXR file")
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        (size,) = struct.unpack("<i", data[end2 + 1 : end2 + 5])
        attrs[name] = data[end2 + 5 : end2 + 5 + size]
        pos = end2 + 5 + size
    pos += 1
    channels, cpos, chl = [], 0, attrs["channels"]
    while chl[cpos] != 0:
        end = chl.index(b"\0", cpos)
        (ptype,) = struct.unpack("<i", chl[end + 1 : end + 5])
        channels.append((chl[cpos:end].decode(), ptype))
        cpos = end + 17
    compression = attrs["compression"][0]
    xmin, ymin, xmax, ymax = struct.unpack("<iiii", attrs["dataWindow"])
    width, height = xmax - xmin + 1, ymax - ymin + 1
    lines_per_chunk = {0: 1, 2: 1, 3: 16}.get(compression)
    if lines_per_chunk is None:
        sys.exit(f"{path}: compression {compression} is not read (only none, ZIPS, ZIP)")
    chunks = (height + lines_per_chunk - 1) // lines_per_chunk
    offsets = struct.unpack(f"<{chunks}Q", data[pos : pos + 8 * chunks])
    result = {name: [0.0] * (width * height) for name in wanted}
    for offset in offsets:
        y, size = struct.unpack("<ii", data[offset : offset + 8])
        block = data[offset + 8 : offset + 8 + size]
        lines = min(lines_per_chunk, ymax + 1 - y)
        expected = lines * width * 4 * len(channels)  # Every channel of this file has 4 bytes.
        if compression and size < expected:
            t = zlib.decompress(block)
            # Undo OpenEXR's predictor (byte deltas biased by 128), then its interleaving
            # of the first and the second half of the bytes.
            t = bytes(itertools.accumulate(t, lambda a, b: (a + b - 128) & 255))
            half = (len(t) + 1) // 2
            block = bytearray(len(t))
            block[0::2], block[1::2] = t[:half], t[half:]
        cpos = 0
        for line in range(lines):
            row = (y - ymin + line) * width
            for name, ptype in channels:
                if name in result:
                    code = "f" if ptype == 2 else "I"
                    values = struct.unpack(f"<{width}{code}", block[cpos : cpos + 4 * width])
                    result[name][row : row + width] = values
                cpos += 4 * width
    return width, height, result


def classify(ours, course, radiance, width, height, near, wide):
    """Yields (x, y, class) for every differing pixel."""
    for y in range(height):
        for x in range(width):
            i = 3 * (y * width + x)
            o, c = ours[i : i + 3], course[i : i + 3]
            if o == c:
                continue
            diff = [ch for ch in range(3) if o[ch] != c[ch]]
            if all(abs(o[ch] - c[ch]) == 1 for ch in diff):
                dist = max(abs(radiance[ch][i // 3] - round(radiance[ch][i // 3])) for ch in diff)
                if dist <= near:
                    yield x, y, "a"
                    continue
                if dist <= wide:
                    yield x, y, "a'"
                    continue
            shifted = False
            for dy, dx in itertools.product((-1, 0, 1), repeat=2):
                nx, ny = x + dx, y + dy
                if (dx or dy) and 0 <= nx < width and 0 <= ny < height:
                    j = 3 * (ny * width + nx)
                    if all(abs(o[ch] - course[j + ch]) <= 1 for ch in range(3)):
                        shifted = True
                        break
            yield x, y, "b" if shifted else "c"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ours")
    parser.add_argument("course")
    parser.add_argument("--moments", help="our moment file (default OURS with .moments.exr)")
    parser.add_argument("--list", nargs="?", const="a a' b c", help="classes to list")
    parser.add_argument("--near", type=float, default=1e-3)
    parser.add_argument("--wide", type=float, default=0.05)
    args = parser.parse_args()
    moments = args.moments or args.ours[: -len(".png")] + ".moments.exr"
    w, h, ours = read_png(args.ours)
    cw, ch, course = read_png(args.course)
    mw, mh, m = read_exr_channels(moments, ("R", "G", "B"))
    if (w, h) != (cw, ch) or (w, h) != (mw, mh):
        sys.exit(f"sizes differ: ours {w}x{h}, course {cw}x{ch}, moments {mw}x{mh}")
    radiance = (m["R"], m["G"], m["B"])
    counts = {"a": 0, "a'": 0, "b": 0, "c": 0}
    listed = args.list.split() if args.list else []
    for x, y, cls in classify(ours, course, radiance, w, h, args.near, args.wide):
        counts[cls] += 1
        if cls in listed:
            i = 3 * (y * w + x)
            rad = " ".join(f"{r[i // 3]:.4f}" for r in radiance)
            print(f"{x} {y}  {' '.join(map(str, ours[i:i+3]))}  "
                  f"{' '.join(map(str, course[i:i+3]))}  {rad}  {cls}")
    total = sum(counts.values())
    share = 100.0 * (1 - total / (w * h))
    print(f"pixels {w * h}  identical {share:.3f} %  differ {total}  " +
          "  ".join(f"{k} {v}" for k, v in counts.items()))


if __name__ == "__main__":
    main()
