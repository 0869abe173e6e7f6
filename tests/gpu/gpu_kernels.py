#!/usr/bin/env python3
"""The OpenCL kernel compiled offline for AMD and NVIDIA GPUs, per course scene.

Each `kernel` line of the budget file names a scene; the kernel's feature set is the one the
host compiles for that scene, read from `raytracer --stats` ("features 0x..."), so a change
of the scene code's feature derivation moves the test with it. Each `budget` line is one
compile (kernel x precision x GPU target) and its limits. Prints one table; with --check,
fails (exit 1) on a compile error, a warning not in the known-warnings list (or a listed one
that no longer appears), a double-precision instruction in a float build, or a figure above
its ceiling, and prints each figure's distance to its target. Exit 77 (skip) where clang-16
or libclc-16 is missing or the course scenes are absent. --ceilings prints the budget lines
again with each ceiling set to today's figure plus 3 %, for lowering them as the kernel
shrinks. The gpu_compile test (tests/gpu/gpu_tests.cmake) and bench/gpu_resources.sh run this.
"""

import argparse
import concurrent.futures
import math
import os
import re
import subprocess
import sys
import tempfile

# No __pycache__ beside the sources: the test runs from the source tree.
sys.dont_write_bytecode = True
import gpu_compile as gc  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SKIP = 77
# The figures a budget line can limit, and the table's columns (name, heading).
METRICS = ("vgprs", "scratch", "vgpr_spills", "frame")
COLUMNS = [("vgprs", "VGPRs"), ("agprs", "of them AGPRs"), ("sgprs", "SGPRs"), ("scratch", "scratch B/lane"),
           ("waves", "waves/SIMD"), ("vgpr_spills", "VGPR spills"), ("sgpr_spills", "SGPR spills"),
           ("frame", "PTX local frame B"), ("ptx_regs", "ptxas regs"),
           ("ptx_stack", "ptxas stack B"), ("ptx_spill_stores", "ptxas spill stores B")]


class InputError(Exception):
    pass


def parse_limit(text, where):
    """'T/C' (target, ceiling) or '-/C' (a ceiling only, no target set yet)."""
    m = re.fullmatch(r"(-|\d+)/(\d+)", text)
    if not m:
        raise InputError("%s: limit '%s' is not TARGET/CEILING or -/CEILING" % (where, text))
    target = None if m.group(1) == "-" else int(m.group(1))
    return target, int(m.group(2))


def read_budgets(path):
    """The kernel lines {name: scene and flags} and budget lines [(kernel, precision,
    target, {metric: (target, ceiling)})] of the budget file."""
    kernels, budgets = {}, []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            where = "%s:%d" % (path, number)
            if not words:
                continue
            if words[0] == "kernel" and len(words) >= 3:
                if words[1] in kernels:
                    raise InputError("%s: kernel '%s' named twice" % (where, words[1]))
                kernels[words[1]] = words[2:]
            elif words[0] == "budget" and len(words) >= 5:
                name, precision, target = words[1:4]
                if name not in kernels:
                    raise InputError("%s: budget for unknown kernel '%s'" % (where, name))
                if precision not in ("float", "double"):
                    raise InputError("%s: precision '%s' is not float or double" % (where, precision))
                if target not in gc.TARGETS:
                    raise InputError("%s: GPU target '%s' is not one of %s" %
                                     (where, target, ", ".join(gc.TARGETS)))
                limits = {}
                for item in words[4:]:
                    metric, _, value = item.partition("=")
                    if metric not in METRICS:
                        raise InputError("%s: metric '%s' is not one of %s" %
                                         (where, metric, ", ".join(METRICS)))
                    limits[metric] = parse_limit(value, where)
                budgets.append((name, precision, target, limits))
            else:
                raise InputError("%s: '%s' is not a kernel or budget line" % (where, line.strip()))
    return kernels, budgets


def read_known_warnings(path):
    """The known warnings, one key per line (tests/gpu/gpu_compile.py: warnings_of)."""
    with open(path, encoding="utf-8") as f:
        return [l.strip() for l in f if l.strip() and not l.startswith("#")]


def all_features(repo):
    """RT_FEATURE_ALL of cl/features.h, as the preprocessor expands it."""
    src = '#include "features.h"\nRT_FEATURE_ALL\n'
    r = subprocess.run([gc.CLANG, "-E", "-P", "-x", "c", "-I", os.path.join(repo, "cl"), "-"],
                       input=src, capture_output=True, text=True, check=True)
    expr = r.stdout.strip().splitlines()[-1]
    if not re.fullmatch(r"[0-9xXa-fA-F()<>|&~+\- ]+", expr):
        raise InputError("cl/features.h: RT_FEATURE_ALL expands to '%s'" % expr)
    return eval(expr)  # Only integer literals and operators, checked above.


# The private-array sizes the host derives from a scene (src/device/kernel_config.cpp), as
# the stats line of its kernel options gives them.
SIZE_DEFINES = re.compile(r"-DRT_(?:BVH_STACK|RAY_TREE_DEPTH)=\d+")


def scene_features(raytracer, scenes, words, work):
    """The feature set the host compiles for a scene and the private-array sizes it
    defines (-DRT_BVH_STACK, -DRT_RAY_TREE_DEPTH), one value over all its cameras."""
    scene = os.path.join(scenes, words[0])
    if not os.path.isfile(scene):
        return None
    out = tempfile.mkdtemp(dir=work)
    r = subprocess.run([raytracer, scene] + words[1:] +
                       ["--device", "cpu", "--resolution-scale", "0.02", "--stats", "--quiet",
                        "--output-dir", out], capture_output=True, text=True)
    values = set(re.findall(r"features (0x[0-9a-f]+)", r.stderr))
    sizes = set(" ".join(SIZE_DEFINES.findall(line)) for line in
                re.findall(r"kernel (?:defines|build options) (.*)", r.stderr))
    if r.returncode != 0 or not values or not sizes:
        raise InputError("%s: raytracer failed (exit %d):\n%s" % (scene, r.returncode, r.stderr))
    if len(values) > 1 or len(sizes) > 1:
        raise InputError("%s: cameras need different kernels (%s): name one with --camera N" %
                         (scene, " ".join(sorted(values | sizes))))
    return int(values.pop(), 16), sizes.pop().split()


def measure(job, features, work, use_ptxas):
    """Compiles one budget line's kernel; returns its figures, warnings and failures."""
    name, precision, target, _ = job
    out = os.path.join(work, "%s.%s.%s.%s" % (name, precision, target,
                                              "s" if gc.TARGETS[target][0] == "amd" else "ptx"))
    rc, stderr = gc.compile_kernel(REPO, features[0], precision, target, out, features[1])
    result = {"figures": {}, "warnings": gc.warnings_of(stderr, REPO), "errors": []}
    if rc != 0:
        result["errors"].append("compile failed (exit %d):\n%s" % (rc, stderr))
        return result
    with open(out, encoding="utf-8") as f:
        text = f.read()
    if gc.TARGETS[target][0] == "amd":
        result["figures"] = gc.amd_resources(stderr, text)
        if "vgprs" not in result["figures"]:
            result["errors"].append("no resource remarks for the render kernel:\n" + stderr)
    else:
        result["figures"] = gc.ptx_resources(text)
        if use_ptxas:
            try:
                result["figures"].update(gc.ptxas_resources(use_ptxas, out, target))
            except RuntimeError as e:
                result["errors"].append(str(e))
    if precision == "float":
        doubles = gc.double_instructions(text, target)
        if doubles:
            result["errors"].append("%d double-precision instructions in a float build, e.g. %s"
                                    % (len(doubles), "; ".join(doubles[:3])))
    os.remove(out)  # Assembly of the large kernels runs to megabytes.
    return result


def ceiling_of(value):
    """Today's figure plus 3 %, so that noise-free growth beyond that trips the check."""
    return int(math.ceil(value * 1.03))


def print_table(budgets, features, results, ptx_note):
    print("| kernel | features | precision | target | " +
          " | ".join(h for _, h in COLUMNS) + " |")
    print("|---|---|---|---|" + "---:|" * len(COLUMNS))
    for job in budgets:
        name, precision, target, _ = job
        fig = results[job[:3]]["figures"]
        cells = []
        for key, _ in COLUMNS:
            if key.startswith("ptx_") and gc.TARGETS[target][0] == "ptx" and ptx_note:
                cells.append(ptx_note)
            else:
                cells.append(str(fig[key]) if key in fig else "-")
        print("| %s | 0x%x | %s | %s | %s |" % (name, features[name][0], precision, target,
                                               " | ".join(cells)))


def check(budgets, results, known, known_path):
    """Prints each limited figure against its ceiling and target; returns the failures."""
    failures = []
    for name, precision, target, limits in budgets:
        label = "%s %s %s" % (name, precision, target)
        r = results[(name, precision, target)]
        failures += ["%s: %s" % (label, e) for e in r["errors"]]
        for metric, (goal, ceiling) in sorted(limits.items()):
            value = r["figures"].get(metric)
            if value is None:
                if not r["errors"]:
                    failures.append("%s: the compile reports no %s" % (label, metric))
                continue
            to_target = ("target %d: %s" % (goal, "met" if value <= goal else "%d over" %
                                            (value - goal))) if goal is not None else "no target"
            verdict = "ok" if value <= ceiling else "FAIL: above the ceiling"
            print("%-44s %-11s %6d  ceiling %6d  %-20s %s" % (label, metric, value, ceiling,
                                                             to_target, verdict))
            if value > ceiling:
                failures.append("%s: %s %d is above its ceiling %d" % (label, metric, value,
                                                                      ceiling))
    seen = {w for r in results.values() for w in r["warnings"]}
    for w in sorted(seen - set(known)):
        failures.append("warning at -Wall -Wextra, not in %s: %s" % (known_path, w))
    for w in sorted(set(known) - seen):
        failures.append("known warning no longer produced (remove it from %s): %s" %
                        (known_path, w))
    for w in sorted(seen & set(known)):
        print("known warning (%s): %s" % (known_path, w))
    return failures


def print_ceilings(budgets, results):
    for name, precision, target, limits in budgets:
        fig = results[(name, precision, target)]["figures"]
        items = ["%s=%s/%d" % (m, "-" if goal is None else goal, ceiling_of(fig.get(m, ceiling)))
                 for m, (goal, ceiling) in limits.items()]
        print("budget %s %s %s %s" % (name, precision, target, " ".join(items)))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--raytracer", required=True, help="the raytracer binary")
    p.add_argument("--scenes", default=os.path.join(REPO, "..", "shared", "scenes"))
    p.add_argument("--budgets", default=os.path.join(HERE, "budgets.txt"))
    p.add_argument("--known-warnings", default=os.path.join(HERE, "known_warnings.txt"))
    p.add_argument("--check", action="store_true", help="fail on a budget or warning")
    p.add_argument("--ceilings", action="store_true", help="print ceilings from today's figures")
    p.add_argument("--ptxas", action="store_true", help="add ptxas's figures where installed")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = p.parse_args()
    reason = gc.missing_tools()
    if reason:
        print("SKIP: " + reason)
        return SKIP
    kernels, budgets = read_budgets(args.budgets)
    known = read_known_warnings(args.known_warnings)
    ptxas = gc.find_ptxas() if args.ptxas else None
    with tempfile.TemporaryDirectory() as work:
        features = {}
        for name, words in kernels.items():
            f = (all_features(REPO), []) if words == ["all"] else \
                scene_features(args.raytracer, args.scenes, words, work)
            if f is None:
                print("SKIP: scene %s of kernel %s is missing (the course scenes belong in %s)"
                      % (words[0], name, args.scenes))
                return SKIP
            features[name] = f
        with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
            futures = {job[:3]: pool.submit(measure, job, features[job[0]], work, ptxas)
                       for job in budgets}
            results = {k: fut.result() for k, fut in futures.items()}
    print("OpenCL kernel compiled offline by %s with libclc (%s), options -cl-std=CL1.2 "
          "-DRT_KERNEL_FEATURES=<features> -DRT_BVH_WIDTH=4 [-DRT_REAL_DOUBLE=1] and the "
          "scene's -DRT_BVH_STACK and -DRT_RAY_TREE_DEPTH:" % (gc.CLANG, gc.LIBCLC))
    for name, (_, sizes) in features.items():
        print("  %s: %s" % (name, " ".join(sizes) or "(the kernel's static bounds)"))
    ptx_note = None
    if args.ptxas and not ptxas:
        ptx_note = "no ptxas"
        print("ptxas columns: ptxas is not installed (NVIDIA's CUDA toolkit), so the PTX rows "
              "have the PTX local frame only")
    elif not ptxas:
        ptx_note = "-"
    print()
    print_table(budgets, features, results, ptx_note)
    print()
    if args.ceilings:
        print_ceilings(budgets, results)
        return 0
    failures = check(budgets, results, known, args.known_warnings) if args.check else \
        [e for r in results.values() for e in r["errors"]]
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputError as e:
        print("gpu_kernels.py: %s" % e, file=sys.stderr)
        sys.exit(2)
    except OSError as e:
        print("gpu_kernels.py: %s" % e, file=sys.stderr)
        sys.exit(2)
