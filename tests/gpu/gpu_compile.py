"""Offline GPU compiles of cl/kernel.cl with Debian's clang-16 and libclc-16.

One compile: the kernel's source with the GPU path's build options of the host
(ClProgramCache::options_for in src/device/cl/cl_program.cpp, without RT_CL_CPU_DEVICE,
which only CPU devices get), for an AMD GPU (the AMDGPU back end's resource remarks) or an
NVIDIA one (PTX; ptxas, where installed, for the registers and spills). Used by
tests/gpu/gpu_kernels.py, the one implementation behind the gpu_compile test and
bench/gpu_resources.sh.
"""

import os
import re
import shutil
import subprocess

CLANG = "clang-16"
# Debian's libclc-16 puts the device libraries here (dpkg -L libclc-16).
LIBCLC = "/usr/lib/clc"
# The targets a budget line can name: family and the clang flags that pick the chip. The
# triples are libclc's own (amdgcn--amdhsa.bc is amdgcn-unknown-amdhsa), so that linking it
# does not warn about a triple mismatch that says nothing about the kernel.
TARGETS = {
    "gfx90a": ("amd", ["-target", "amdgcn-unknown-amdhsa", "-mcpu=gfx90a"]),
    "gfx1030": ("amd", ["-target", "amdgcn-unknown-amdhsa", "-mcpu=gfx1030"]),
    "gfx1100": ("amd", ["-target", "amdgcn-unknown-amdhsa", "-mcpu=gfx1100"]),
    "sm_90": ("ptx", ["-target", "nvptx64-unknown-nvidiacl", "-Xclang", "-target-cpu",
                      "-Xclang", "sm_90", "-Xclang", "-target-feature", "-Xclang", "+ptx78"]),
}
LIBRARY = {"amd": "amdgcn--amdhsa.bc", "ptx": "nvptx64--nvidiacl.bc"}


def missing_tools():
    """The reason the compiles cannot run here, or None."""
    if shutil.which(CLANG) is None:
        return CLANG + " is not installed (Debian package clang-16; tools/install-deps.sh)"
    for lib in LIBRARY.values():
        if not os.path.isfile(os.path.join(LIBCLC, lib)):
            return os.path.join(LIBCLC, lib) + " is missing (Debian package libclc-16)"
    return None


def find_ptxas():
    """ptxas from PATH or the CUDA toolkit's default place (not a Debian package), or None."""
    return shutil.which("ptxas") or shutil.which("ptxas", path="/usr/local/cuda/bin")


def build_options(features, precision, sizes=()):
    """The -cl-std/-D options of the host's GPU path for this feature set and precision,
    with the scene's private-array sizes (`sizes`: -DRT_BVH_STACK=N, -DRT_RAY_TREE_DEPTH=N)."""
    o = ["-cl-std=CL1.2", "-DRT_KERNEL_FEATURES=%d" % features, "-DRT_BVH_WIDTH=4"] + list(sizes)
    if precision == "double":
        o.append("-DRT_REAL_DOUBLE=1")
    return o


def compile_kernel(repo, features, precision, target, out_path, sizes=()):
    """Compiles cl/kernel.cl to assembly (AMD) or PTX at out_path; returns (rc, stderr)."""
    family, flags = TARGETS[target]
    cmd = [CLANG, "-x", "cl"] + build_options(features, precision, sizes) + flags
    cmd += ["-nogpulib", "-Xclang", "-finclude-default-header", "-Xclang",
            "-mlink-builtin-bitcode", "-Xclang", os.path.join(LIBCLC, LIBRARY[family]), "-O3",
            "-Wall", "-Wextra", "-fno-caret-diagnostics", "-fno-color-diagnostics"]
    if family == "amd":
        cmd.append("-Rpass-analysis=kernel-resource-usage")
    cmd += ["-S", "-o", out_path, os.path.join(repo, "cl", "kernel.cl")]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=repo)
    return r.returncode, r.stderr


# "cl/kernel.cl:12:1: remark:     VGPRs: 247 [-Rpass-analysis=kernel-resource-usage]"
REMARK = re.compile(r"remark:\s+([^:\[]+?)(?: \[[\w/]+\])?: (\S+) \[-Rpass-analysis")
AMD_KEYS = {"VGPRs": "vgprs", "AGPRs": "agprs", "SGPRs": "sgprs",
            "ScratchSize": "scratch", "Occupancy": "waves", "SGPRs Spill": "sgpr_spills",
            "VGPRs Spill": "vgpr_spills", "LDS Size": "lds"}


def amd_resources(stderr, asm, entry="render"):
    """The AMDGPU back end's figures for one kernel entry, from its remarks; the VGPRs are
    the code object's .vgpr_count, which on gfx90a adds the AGPRs (one register file of 512
    per lane: the count that decides the occupancy) to the remark's architectural VGPRs."""
    found, current = {}, None
    for line in stderr.splitlines():
        m = REMARK.search(line)
        if not m:
            continue
        key, value = m.group(1).strip(), m.group(2)
        if key == "Function Name":
            current = value
        elif current == entry and key in AMD_KEYS:
            found[AMD_KEYS[key]] = int(value)
    for chunk in asm.split("\n  - ")[1:]:
        if re.search(r"^\s+\.name:\s+%s$" % re.escape(entry), chunk, re.M):
            m = re.search(r"^\s+\.vgpr_count:\s+(\d+)$", chunk, re.M)
            if m:
                found["vgprs"] = int(m.group(1))
    return found


def ptx_resources(ptx_text, entry="render"):
    """The local (stack) frame of one PTX entry with the deepest chain of the functions it
    calls (the compiler keeps the largest of them out of line): per-thread local memory."""
    bodies = dict(re.findall(r"^(?:\.visible )?\.(?:entry|func)\s+(?:\([^)]*\)\s*)?(\w+)\((.*?)^\}",
                             ptx_text, re.S | re.M))

    def frame(name, seen):
        body = bodies.get(name, "")
        own = sum(int(n) for n in re.findall(r"\.local \.align \d+ \.b8\s+\S+\[(\d+)\]", body))
        callees = set(re.findall(r"\bcall(?:\.uni)?\s+(?:\([^)]*\),\s*)?(\w+)", body)) - seen
        return own + max([frame(c, seen | {c}) for c in callees], default=0)

    return {"frame": frame(entry, {entry})}


def ptxas_resources(ptxas, ptx_path, target, entry="render"):
    """ptxas -v's registers and cumulative stack of one entry, and the spill bytes of it and
    of every function it keeps out of line (all but the other entry, rt_sizes)."""
    r = subprocess.run([ptxas, "-arch=" + target, "-v", "-o", os.devnull, ptx_path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("ptxas failed on %s:\n%s" % (ptx_path, r.stderr))
    out = {"ptx_spill_stores": 0}
    for name, block in re.findall(r"Function properties for (\w+)\n(.*?)(?=ptxas info\s+: Compiling|"
                                  r"ptxas info\s+: Function properties|\Z)", r.stderr, re.S):
        if name == "rt_sizes":
            continue
        m = re.search(r"(\d+) bytes spill stores", block)
        out["ptx_spill_stores"] += int(m.group(1)) if m else 0
        m = re.search(r"Used (\d+) registers.*?(\d+) bytes cumulative stack size", block)
        if name == entry and m:
            out["ptx_regs"], out["ptx_stack"] = int(m.group(1)), int(m.group(2))
    return out


# Instructions that compute in double: AMD's VALU/SALU f64 opcodes, PTX's .f64 types.
AMD_F64 = re.compile(r"^\s*[vs]_\w*f64")
PTX_F64 = re.compile(r"^\s*(?:@!?%\w+\s+)?[a-z][\w.]*\.f64\b")


def double_instructions(text, target):
    """The instruction lines of the assembly that use double precision."""
    pattern = AMD_F64 if TARGETS[target][0] == "amd" else PTX_F64
    return [line.strip() for line in text.splitlines() if pattern.match(line)]


# "cl/film/../material/glossy.h:19:68: warning: unused parameter 'sd' [-Wunused-parameter]"
DIAGNOSTIC = re.compile(r"^(.+?):(\d+):\d+: warning: (.*)$")


def warnings_of(stderr, repo):
    """Each warning of a compile as a key that survives edits elsewhere in the file: the
    file, the function whose first line holds the warning (when it does), the message."""
    keys = []
    for line in stderr.splitlines():
        if "warning:" not in line or " remark:" in line:
            continue
        m = DIAGNOSTIC.match(line)
        if not m:
            keys.append(line.strip())
            continue
        path = os.path.relpath(os.path.normpath(os.path.join(repo, m.group(1))), repo)
        where = path
        try:
            with open(os.path.join(repo, path), encoding="utf-8") as f:
                source = f.read().splitlines()[int(m.group(2)) - 1]
            fn = re.search(r"([A-Za-z_]\w*)\s*\(", source)
            if fn:
                where += " " + fn.group(1)
        except (OSError, IndexError):
            pass
        keys.append("%s: %s" % (where, m.group(3)))
    return keys
