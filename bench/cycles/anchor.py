#!/usr/bin/env python3
"""The path tracer against Blender Cycles on the same scenes: run by bench/cycles_anchor.sh,
whose header describes the options and docs/benchmarks.md the table."""
import argparse
import os
import resource
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENES = {
    "diffuse": "hw6/pathTracing/cornellbox_jaroslav_path_diffuse.xml",
    "glass": "hw6/pathTracing/cornellbox_jaroslav_path_glass.xml",
}
CAMERA = 2  # NextEventEstimation ImportanceSampling, no roulette.
REF_SEED = 1000003  # Far from the measured runs' seeds 1, 2, ...: independent streams.


def parse():
    p = argparse.ArgumentParser(prog="bench/cycles_anchor.sh")
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--work", default=None, help="reference cache and images (BUILD/cycles_anchor)")
    p.add_argument("--blender", default="blender")
    p.add_argument("--scenes-dir", default=os.path.join(ROOT, "..", "shared", "scenes"))
    p.add_argument("--scenes", default="diffuse glass")
    p.add_argument("--devices", default="cpu cl")
    p.add_argument("--modes", default=None, help="our --path-estimator values")
    p.add_argument("--spp", default="16 64 256")
    p.add_argument("--reps", type=int, default=3)
    p.add_argument("--ref-spp", type=int, default=4096)
    p.add_argument("--scale", type=float, default=0.5)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--extra", default="", help="more options for every render of ours")
    p.add_argument("--quick", action="store_true")
    a = p.parse_args()
    if a.quick:  # A smoke check of a few minutes: 64 x 64, few samples, one repetition.
        a.scale, a.spp, a.reps, a.ref_spp = 0.125, "4 16", 1, 1024
    a.work = a.work or os.path.join(a.build, "cycles_anchor")
    a.spp = [int(v) for v in a.spp.split()]
    a.scenes = a.scenes.split()
    a.devices = a.devices.split()
    for s in a.scenes:
        if s not in SCENES:
            p.error("--scenes: unknown scene %s (known: %s)" % (s, " ".join(SCENES)))
        if not os.path.isfile(os.path.join(a.scenes_dir, SCENES[s])):
            p.error("--scenes-dir: %s is missing" % os.path.join(a.scenes_dir, SCENES[s]))
    if min(a.spp) < 2 or a.reps < 1 or a.ref_spp < max(a.spp):
        p.error("--spp values must be >= 2, --reps >= 1, --ref-spp >= the largest --spp")
    return a


def timed(cmd, log):
    """Runs cmd; returns its children's user + system CPU-seconds (getrusage)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(log, "w") as out:
        rc = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if rc != 0:
        sys.exit("cycles_anchor: %s failed (exit %d); see %s" % (cmd[0], rc, log))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


class Runner:
    def __init__(self, a):
        self.a = a
        self.raytracer = os.path.join(a.build, "raytracer")
        self.metrics = os.path.join(a.build, "cycles_metrics")
        self.shared = a.scenes_dir
        help_text = subprocess.run([self.raytracer, "--help"], capture_output=True,
                                   text=True).stdout
        self.has_estimator = "--path-estimator" in help_text
        if a.modes is None:
            a.modes = "course mis" if self.has_estimator else "course"
        self.modes = a.modes.split()
        if self.modes != ["course"] and not self.has_estimator:
            sys.exit("cycles_anchor: --modes %s: this raytracer has no --path-estimator" % a.modes)
        os.makedirs(a.work, exist_ok=True)

    def scene(self, name):
        return os.path.join(self.shared, SCENES[name])

    def image_name(self, name):
        # The camera's ImageName; the renderer writes it into --output-dir.
        import xml.etree.ElementTree as ET
        cams = list(ET.parse(self.scene(name)).getroot().find("Cameras"))
        return cams[CAMERA].findtext("ImageName").strip()

    def ours(self, name, device, mode, spp, seed, out):
        """Renders our image to out (EXR); returns CPU-seconds."""
        d = out + ".d"
        os.makedirs(d, exist_ok=True)
        cmd = [self.raytracer, self.scene(name), "--camera", str(CAMERA), "--spp", str(spp),
               "--seed", str(seed), "--resolution-scale", repr(self.a.scale), "--output-dir", d,
               "--device", device, "--quiet"]
        if device == "cpu":
            cmd += ["--threads", str(self.a.threads)]
        if self.has_estimator:
            cmd += ["--path-estimator", mode]
        cmd += self.a.extra.split()
        t = timed(cmd, out + ".log")
        os.replace(os.path.join(d, self.image_name(name)), out)
        return t

    def cycles(self, name, spp, seed, out):
        cmd = [self.a.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
               os.path.join(HERE, "scene_to_blender.py"), "--", self.scene(name), "--camera",
               str(CAMERA), "--scale", repr(self.a.scale), "--spp", str(spp), "--seed",
               str(seed), "--threads", str(self.a.threads), "--out", out]
        return timed(cmd, out + ".log")

    def figures(self, *args):
        r = subprocess.run([self.metrics] + list(args), capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("cycles_anchor: cycles_metrics %s: %s" % (" ".join(args), r.stderr.strip()))
        return r.stdout.split()

    def reference(self, name, who, mode=None):
        """The cached converged reference of `who` ("ours" in path tracer mode `mode`, or
        "cycles") for scene name: each of our modes converges to its own image (the course's
        path length differs from Cycles'), so each is measured against its own."""
        tag = "%s_%s_s%g_%dspp.exr" % (who if mode is None else who + "_" + mode, name,
                                        self.a.scale, self.a.ref_spp)
        path = os.path.join(self.a.work, "ref_" + tag)
        if os.path.isfile(path):
            return path
        print("rendering the %s reference of %s at %d spp (cached as %s)" %
              (who, name, self.a.ref_spp, path), flush=True)
        tmp = path + ".part.exr"
        if who == "ours":
            t = self.ours(name, "cpu", mode, self.a.ref_spp, REF_SEED, tmp)
        else:
            t = self.cycles(name, self.a.ref_spp, REF_SEED, tmp)
        os.replace(tmp, path)
        print("  %.0f CPU-s" % t, flush=True)
        return path


def table(a, rows, refs):
    fmt = lambda v: "%.3g" % v
    print("\n| scene | device | renderer | spp | CPU-s | sampling CPU-s | relMSE | relMSE "
          "trimmed | efficiency | eff. trimmed | ours/Cycles | ours/Cycles trimmed | "
          "ours/Cycles sampling |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for key in sorted(rows, key=lambda k: (a.scenes.index(k[0]), k[3], k[1] != "-", k[1], k[2])):
        scene, device, who, spp = key
        r = rows[key]
        base = rows[(scene, "-", "cycles", spp)]
        cells = [scene, device, who, str(spp), "%.2f" % r["t"], "%.2f" % r["ts"], fmt(r["e"]),
                 fmt(r["et"]), fmt(1 / (r["e"] * r["t"])), fmt(1 / (r["et"] * r["t"]))]
        if who == "cycles":
            cells += ["", "", ""]
        else:
            cells += ["%.2f" % (base["e"] * base["t"] / (r["e"] * r["t"])),
                      "%.2f" % (base["et"] * base["t"] / (r["et"] * r["t"])),
                      "%.2f" % (base["e"] * base["ts"] / (r["e"] * r["ts"]))]
        print("| " + " | ".join(cells) + " |")


def main():
    a = parse()
    run = Runner(a)
    print("scenes %s, camera %d, resolution scale %g, spp %s, %d repetitions, references at "
          "%d spp; our modes: %s; devices: %s; %d threads" %
          (" ".join(a.scenes), CAMERA, a.scale, " ".join(map(str, a.spp)), a.reps, a.ref_spp,
           " ".join(run.modes), " ".join(a.devices), a.threads), flush=True)
    refs = {}
    print("\nreference agreement (Cycles / ours; 8x8 blocks, relative residual RMS):")
    for s in a.scenes:
        refs[(s, "cycles")] = run.reference(s, "cycles")
        for m in run.modes:
            refs[(s, m)] = run.reference(s, "ours", m)
            ratio = run.figures("agree", refs[(s, m)], refs[(s, "cycles")])
            print("  %s, %s: mean ratio %s (R %s G %s B %s), block residual RMS %s, after the "
                  "ratio %s (%s blocks)" %
                  ((s, m) + tuple(ratio[1:5]) + (ratio[6], ratio[8], ratio[10])), flush=True)
    configs = [("-", "cycles")] + [(d, m) for d in a.devices for m in run.modes]
    img = os.path.join(a.work, "run.exr")
    for s in a.scenes:  # Warm-up, untimed: the OpenCL kernel cache, the file cache.
        for d, m in configs:
            if d == "-":
                run.cycles(s, 1, 1, img)
            else:
                run.ours(s, d, m, 1, 1, img)
    samples = {}
    for rep in range(a.reps):
        for s in a.scenes:
            for spp in [1] + a.spp:
                for d, m in configs:  # Interleaved: A B A B.
                    seed = rep + 1
                    if d == "-":
                        t = run.cycles(s, spp, seed, img)
                    else:
                        t = run.ours(s, d, m, spp, seed, img)
                    e = et = 0.0
                    if spp > 1:
                        ref = refs[(s, "cycles" if d == "-" else m)]
                        f = run.figures("error", ref, img)
                        e, et = float(f[1]), float(f[3])
                    samples.setdefault((s, d, "cycles" if d == "-" else m, spp), []).append(
                        (t, e, et))
        print("repetition %d of %d done" % (rep + 1, a.reps), flush=True)
    rows = {}
    med = lambda v: statistics.median(v)
    for (s, d, who, spp), v in samples.items():
        if spp == 1:
            continue
        t = med([x[0] for x in v])
        t1 = med([x[0] for x in samples[(s, d, who, 1)]])
        rows[(s, d, who, spp)] = {"t": t, "ts": max(t - t1, 1e-3) * spp / (spp - 1),
                                  "e": med([x[1] for x in v]), "et": med([x[2] for x in v])}
    table(a, rows, refs)
    print("\nCPU-s: user + system of the process (median); sampling CPU-s: minus a 1 spp run, "
          "scaled to spp; relMSE: mean over pixels and R, G, B of (x - ref)^2 / (ref^2 + 1e-2) "
          "against the renderer's own reference (median); trimmed: the 0.1 % largest terms "
          "left out; efficiency: 1 / (relMSE x CPU-s); ours/Cycles: our efficiency over "
          "Cycles' (sampling: with sampling CPU-s).")


if __name__ == "__main__":
    main()
