#!/usr/bin/env python3
"""Explains, pixel by pixel, where our render of a course scene differs from the course's.

usage: tools/explain_pixels.py ENSEMBLE_DIR COURSE.png [--csv OUT.csv] [--crop X0 Y0 X1 Y1]
                               [--markdown] [--list-unexplained] [--model NAME=FILE ...]

ENSEMBLE_DIR is what tools/explain_ensemble.py wrote: members.tsv and one render per
member, "base" being the unperturbed one (with its moment file). Each pixel where base
differs from COURSE.png gets the first mechanism that explains it:
  rounding:FAMILY  some member of the ensemble attains the course's 8-bit value in all three
                   channels: the pixel is decided by rounding of that member's size.
                   Families, smallest first: arith (--precision double, --camera-rays
                   exact, --frame world, --hit-point surface), camera (Position, Gaze,
                   NearDistance by 1-2 ulps), light (point lights by 1 ulp), epsilon
                   (ShadowRayEpsilon by 1-2 ulps of the camera's coordinates), sphere (r^2
                   by 1/4 to 4 ulps of |centre - eye|^2), combined (two of these at once),
                   model (an independent model's value, --model: tools/whitted_probe.py
                   with the course's float sphere test), offset (--ray-offset robust,
                   larger than rounding on large coordinates). The member named is the
                   first attaining one in that order, smaller steps first; the CSV lists
                   every attaining member.
  bracketed:FAMILY no member attains it, but between our value and some member's lies the
                   course's, in every channel: the pixel passes from ours to the member's
                   over a perturbation of that member's size (a silhouette that the
                   member's step crosses from hit to miss, or a steep gradient). Weaker: the
                   value need not be continuous in between. The CSV lists the members in
                   parentheses.
  boundary         neither, the pixel is one level off in every differing
                   channel and our unclamped radiance lies within 0.05 of a whole level
                   (classify_pixels.py's a and a'): the truncation's side is decided by
                   rounding smaller than the members resolved.
  edge             our value occurs (within a level) at a neighbouring pixel of the
                   course's image (classify_pixels.py's b): an edge displaced by under a
                   pixel.
  convention       none of these, but a convention member attains it (--reflection-offset
                   facing, --shadow-offset geometric, --cull-back-faces): these change
                   every pixel of a kind, so this says only that the course may treat the
                   pixel otherwise; it does not count as explained.
  unexplained      none of these.
Prints the table of mechanisms; per member, how many differing pixels it attains, of how
many it is the smallest attaining member, how many pixels it changes and how many of the
identical ones it breaks (its reach: a member that changed every pixel could match by
chance); as a control, at how many differing pixels some member attains (or brackets) the
mirror value 2 ours - course instead (chance would do both about equally); and the
unexplained pixels. Only the Python standard library is used.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from classify_pixels import classify, read_exr_channels, read_png  # noqa: E402

FAMILIES = (("arith", ("double", "exact", "world", "surface", "ray")),
            ("camera", ("pos", "posb", "posc", "posd", "gaze", "gazeb", "gazec", "gazed", "near")),
            ("light", ("light", "lightb", "lightc", "lightd")),
            ("epsilon", ("eps",)),
            ("sphere", ("r2",)),
            ("combined", ()),
            ("model", ()),
            ("offset", ("robust",)),
            ("convention", ("facing", "geometric", "cull")))
# Conventions change every pixel of a kind (5 % of grass_desert), so they explain nothing:
# a pixel only they attain is listed as "convention", after the weaker classes.
EVIDENCE = [name for name, _ in FAMILIES if name != "convention"]
MECHANISMS = ([f"rounding:{name}" for name in EVIDENCE] + [f"bracketed:{name}" for name in EVIDENCE]
              + ["boundary", "edge", "convention", "unexplained"])


def family(member):
    if "&" in member:
        return "combined"
    if member.startswith("model:"):
        return "model"
    stem = re.sub(r"[+-][\d.]+$", "", member)
    for name, stems in FAMILIES:
        if stem in stems:
            return name
    return "other"


def rank(member):
    """Sort key: family order, then the perturbation's size in ulps."""
    names = [name for name, _ in FAMILIES]
    fam = family(member)
    size = re.search(r"[+-]([\d.]+)$", member.split("&")[-1])
    size = float(size.group(1)) if size else 0.0
    return (names.index(fam) if fam in names else len(names), size, member)


def read_members(directory):
    members = []
    with open(os.path.join(directory, "members.tsv")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            name, what, step, image = line.rstrip("\n").split("\t")
            members.append((name, what, step, os.path.join(directory, image)))
    return members


def read_model(path, base, width):
    """An image that is base except at the pixels tools/whitted_probe.py --batch evaluated
    (its lines "X Y  model R G B  course ..."), which take the model's 8-bit value."""
    image = bytearray(base)
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 6 and fields[0].isdigit() and fields[2] == "model":
                i = 3 * (int(fields[1]) * width + int(fields[0]))
                image[i : i + 3] = bytes(int(v) for v in fields[3:6])
    return image


def explain(base, course, radiance, images, width, height, crop):
    """Yields (x, y, class, mechanism, attaining members) for every differing pixel."""
    x0, y0, x1, y1 = crop
    order = sorted(images, key=rank)
    for x, y, cls in classify(base, course, radiance, width, height, 1e-3, 0.05):
        if not (x0 <= x < x1 and y0 <= y < y1):
            continue
        i = 3 * (y * width + x)
        target = course[i : i + 3]
        attaining = [m for m in order if images[m][i : i + 3] == target]
        evidence = [m for m in attaining if family(m) != "convention"]
        ours = base[i : i + 3]
        between = [m for m in order if family(m) != "convention" and
                   all(min(o, v) <= t <= max(o, v)
                       for o, v, t in zip(ours, images[m][i : i + 3], target))]
        if evidence:
            mechanism = "rounding:" + family(evidence[0])
        elif between:
            mechanism = "bracketed:" + family(between[0])
            attaining = ["(" + m + ")" for m in between]
        elif cls in ("a", "a'"):
            mechanism = "boundary"
        elif cls == "b":
            mechanism = "edge"
        elif attaining:
            mechanism = "convention"
        else:
            mechanism = "unexplained"
        yield x, y, cls, mechanism, attaining


def mirror_control(rows, base, course, images, width):
    """Differing pixels at which some member attains the mirror value 2 ours - course
    (clamped to 0-255): as far from ours as the course's value, on the other side. An
    ensemble that matched the course by chance would attain it about as often."""
    hits = brackets = 0
    for x, y, *_ in rows:
        i = 3 * (y * width + x)
        ours = base[i : i + 3]
        mirror = bytes(min(255, max(0, 2 * o - c)) for o, c in zip(ours, course[i : i + 3]))
        hits += any(img[i : i + 3] == mirror for img in images.values())
        brackets += any(all(min(o, v) <= t <= max(o, v) for o, v, t in zip(ours, img[i : i + 3], mirror))
                        for img in images.values())
    return hits, brackets


def member_reach(base, course, img, width, crop):
    """(pixels changed from base, differing pixels it attains, identical pixels it breaks)."""
    x0, y0, x1, y1 = crop
    changed = attains = breaks = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            i = 3 * (y * width + x)
            b, c, m = base[i : i + 3], course[i : i + 3], img[i : i + 3]
            if m != b:
                changed += 1
                attains += b != c and m == c
                breaks += b == c
    return changed, attains, breaks


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ensemble")
    parser.add_argument("course")
    parser.add_argument("--csv", help="write one line per differing pixel here")
    parser.add_argument("--crop", nargs=4, type=int, metavar=("X0", "Y0", "X1", "Y1"))
    parser.add_argument("--markdown", action="store_true", help="print tables as Markdown")
    parser.add_argument("--list-unexplained", action="store_true")
    parser.add_argument("--model", action="append", default=[], metavar="NAME=FILE",
                        help="an independent model's values at the pixels it evaluated "
                             "(tools/whitted_probe.py --batch output): a member of family "
                             "model named model:NAME")
    args = parser.parse_args()
    members = read_members(args.ensemble)
    base_png = dict((m[0], m[3]) for m in members)["base"]
    w, h, base = read_png(base_png)
    cw, ch, course = read_png(args.course)
    if (w, h) != (cw, ch):
        sys.exit(f"{args.course}: {cw}x{ch}, our render {w}x{h}")
    _, _, m = read_exr_channels(base_png[: -len(".png")] + ".moments.exr", ("R", "G", "B"))
    radiance = (m["R"], m["G"], m["B"])
    images = {}
    for name, _, _, path in members:
        if name != "base":
            mw, mh, images[name] = read_png(path)
            if (mw, mh) != (w, h):
                sys.exit(f"{path}: {mw}x{mh}, base {w}x{h}")
    for spec in args.model:
        name, path = spec.split("=", 1)
        images["model:" + name] = read_model(path, base, w)
        members.append(("model:" + name, f"tools/whitted_probe.py model ({path})", "", path))
    crop = tuple(args.crop) if args.crop else (0, 0, w, h)
    rows = list(explain(base, course, radiance, images, w, h, crop))
    counts = {k: 0 for k in MECHANISMS}
    for row in rows:
        counts[row[3]] += 1
    pixels = (crop[2] - crop[0]) * (crop[3] - crop[1])
    bar = "|" if args.markdown else ""
    attained = sum(1 for row in rows if row[3].startswith("rounding"))
    bracketed = attained + sum(1 for row in rows if row[3].startswith("bracketed"))
    hits, brackets = mirror_control(rows, base, course, {
        k: v for k, v in images.items() if family(k) != "convention"}, w)
    print(f"pixels {pixels}  differ {len(rows)}  unexplained {counts['unexplained']}")
    print(f"control: members attain the course's value at {attained} pixels, the mirror value at "
          f"{hits}; attain or bracket the course's at {bracketed}, the mirror value at {brackets}")
    print(f"{bar} mechanism {bar} pixels {bar}")
    if args.markdown:
        print("|---|---:|")
    for k in MECHANISMS:
        print(f"{bar} {k} {bar} {counts[k]} {bar}")
    # first: the pixels this member is the smallest attaining member of (the one named).
    first = {}
    for row in rows:
        if row[3].startswith("rounding"):
            first[row[4][0]] = first.get(row[4][0], 0) + 1
    print(f"\n{bar} member {bar} what it changes {bar} 1 ulp {bar} attains {bar} first {bar} "
          f"changes {bar} breaks {bar}")
    if args.markdown:
        print("|---|---|---:|---:|---:|---:|---:|")
    for name, what, step, _ in sorted(members, key=lambda m: rank(m[0])):
        if name != "base":
            changed, attains, breaks = member_reach(base, course, images[name], w, crop)
            print(f"{bar} {name} {bar} {what} {bar} {step or '-'} {bar} {attains} {bar} "
                  f"{first.get(name, 0)} {bar} {changed} {bar} {breaks} {bar}")
    if args.list_unexplained:
        for x, y, cls, mech, _ in rows:
            if mech == "unexplained":
                i = 3 * (y * w + x)
                rad = " ".join(f"{r[i // 3]:.4f}" for r in radiance)
                print(f"unexplained {x} {y}  ours {' '.join(map(str, base[i:i+3]))}  course "
                      f"{' '.join(map(str, course[i:i+3]))}  radiance {rad}  class {cls}")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("x,y,ours,course,radiance,class,mechanism,attaining members\n")
            for x, y, cls, mech, attaining in rows:
                i = 3 * (y * w + x)
                rad = " ".join(f"{r[i // 3]:.4f}" for r in radiance)
                f.write(f"{x},{y},{' '.join(map(str, base[i:i+3]))},"
                        f"{' '.join(map(str, course[i:i+3]))},{rad},{cls},{mech},"
                        f"{' '.join(attaining)}\n")


if __name__ == "__main__":
    main()
