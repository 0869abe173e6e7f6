#!/usr/bin/env python3
"""Rewrites the computation in cl/ over the precision-neutral scalar type of cl/util/real.h.

`--precision double` needs every computed value of the shared math to be `real` (float or
double by build), while the device arrays keep their float layouts. This script does the
mechanical part: in the code (not the comments) of every header of cl/ that is not a
storage header, float3 -> real3, float2 -> real2, float -> real, make_float3/2 ->
make_real3/2, a float literal passed straight to fmin/fmax -> RT_R(literal), and exp/pow/sin/cos ->
ExpR/PowR/SinR/CosR (cl/util/transcendental.h). It is idempotent, so it can be re-run on headers that arrive in float
(after a merge); what it cannot know (a value read from an array needs ToReal3, a result
stored into one ToFloat3) the compilers point out: OpenCL C and the CPU reference's double
build have no implicit conversion between float3 and double3.

Usage: tools/to_real.py [FILE...]   (default: every header under cl/)
"""
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Headers that define storage (buffer layouts) or precision-neutral helpers: left as is.
STORAGE = {
    "cl/compat.h", "cl/data_arrays.h", "cl/features.h", "cl/film/film_types.h",
    "cl/scene_types.h", "cl/bvh/simd.h", "cl/texture/texture_types.h", "cl/util/real.h",
    "cl/util/hash.h", "cl/util/transcendental.h",
}
RULES = [
    (re.compile(r"\bmake_float3\b"), "make_real3"),
    (re.compile(r"\bmake_float2\b"), "make_real2"),
    (re.compile(r"\bfloat3\b"), "real3"),
    (re.compile(r"\bfloat2\b"), "real2"),
    (re.compile(r"\bfloat\b"), "real"),
    # A float literal as a direct argument of fmin/fmax: OpenCL C finds fmax(float, double)
    # ambiguous, so the literal takes the computation's type (RT_R of cl/util/real.h).
    (re.compile(r"\b(fmin|fmax)\((-?[0-9]+\.[0-9]*)f\s*,"), r"\1(RT_R(\2),"),
    (re.compile(r"\b(fmin|fmax)(\([^(),]*(?:\([^()]*\)[^(),]*)*),\s*(-?[0-9]+\.[0-9]*)f\)"),
     r"\1\2, RT_R(\3))"),
    # Library exp/pow/sin/cos round differently on PoCL and glibc in double; ExpR..CosR of
    # cl/util/transcendental.h are the library's in float and its portable ones in double.
    (re.compile(r"\bexp\("), "ExpR("),
    (re.compile(r"\bpow\("), "PowR("),
    (re.compile(r"\bsin\("), "SinR("),
    (re.compile(r"\bcos\("), "CosR("),
]


# Pointers into the scene's global arrays read storage, which stays float.
STORAGE_POINTER = re.compile(r"\b(RT_GLOBAL\s+(?:const\s+)?)float(\d?)\b")


def convert_code(code):
    code = STORAGE_POINTER.sub(r"\1STORAGE_FLOAT\2", code)
    for pattern, repl in RULES:
        code = pattern.sub(repl, code)
    return code.replace("STORAGE_FLOAT", "float")


def convert(text):
    out = []
    in_block = False
    for line in text.split("\n"):
        if in_block:
            out.append(line)
            in_block = "*/" not in line
            continue
        stripped = line.lstrip()
        if stripped.startswith("/*"):
            out.append(line)
            in_block = "*/" not in line
            continue
        # Code before a trailing // comment; string literals do not occur in cl/.
        cut = line.find("//")
        code, comment = (line, "") if cut < 0 else (line[:cut], line[cut:])
        out.append(convert_code(code) + comment)
    return "\n".join(out)


def main(argv):
    files = [pathlib.Path(a).resolve() for a in argv] or sorted((ROOT / "cl").rglob("*.h"))
    for path in files:
        rel = path.relative_to(ROOT).as_posix()
        if rel in STORAGE:
            continue
        text = path.read_text()
        new = convert(text)
        if new != text:
            path.write_text(new)
            # Shorter names can let clang-format join lines; keep the files formatted.
            if shutil.which("clang-format"):
                subprocess.run(["clang-format", "-i", str(path)], check=False)
            print("converted", rel)


if __name__ == "__main__":
    main(sys.argv[1:])
