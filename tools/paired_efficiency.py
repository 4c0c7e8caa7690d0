#!/usr/bin/env python3
"""Equal-time efficiency of estimator B against estimator A by concurrent pairs: each pair renders A and B at the
same time, each `vkmc render` on one lavapipe thread, so that the machine's swings (its neighbours, its slow and
fast minutes) reach both renders of a pair alike. They are not pinned: pinned to a core each, two renders of one
configuration reached 0.75-1.3x each other's samples in 16 s (this VM's cores slow down one at a time); left to
the scheduler, which moves them between the cores, within 1%. A pair's ratio is
efficiency(B) / efficiency(A), efficiency = 1 / (relMSE against the reference x seconds). The seeds change from
pair to pair; a pair's two renders share their seed (common random numbers: where B's samples are
A's, as where `--rr ears` falls back to throughput roulette, their errors cancel in the ratio and what is left is
what B's time bought; --independent-seeds gives each render its own). docs/ears.md, "Concurrent pairs", says
why: rendered one after the other, two renders of the same configuration read 0.74-1.43x each other on this
machine; side by side they read within a few percent.

  python3 tools/paired_efficiency.py SCENE [--a EST.json] [--b EST.json] [--seconds S] [--pairs N]
      [--width W --height H] [--reference EXR | --reference-spp N | --reference-constant L]
      [--independent-seeds] [--json OUT] [--vkmc PATH]

A and B default to scenes/estimators/baseline.json (throughput roulette) and rr_ears_guard.json (`--rr ears` as
it runs by default); --b the same file as --a is the method's control. Without --reference, a reference is
rendered with A (--reference-spp samples, both threads) and cached by what determines it in
$VKMC_CACHE_DIR/paired (else ~/.cache/vkmc/paired). Prints each pair and the geometric mean of the ratios with a
95% interval from their measured spread (Student t on the log-ratios), and the median.
"""
import argparse
import hashlib
import json
import math
import os
import statistics
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Two-sided 95% Student t quantiles by degrees of freedom (beyond the table: the normal's 1.96 is close enough).
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228,
       12: 2.179, 15: 2.131, 20: 2.086, 30: 2.042}


def t95(dof):
    keys = sorted(k for k in T95 if k <= dof)
    return T95[keys[-1]] if dof <= 30 else 1.96


def fail(message):
    print(f"paired_efficiency: {message}", file=sys.stderr)
    sys.exit(1)


def cache_dir():
    if os.environ.get("VKMC_CACHE_DIR"):
        return os.path.join(os.environ["VKMC_CACHE_DIR"], "paired")
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "vkmc", "paired")


def digest(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else str(p).encode())
        h.update(b"\0")
    return h.hexdigest()[:16]


def file_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def render(args, estimator, out_exr, report, extra, threads=None):
    cmd = [args.vkmc, "render", args.scene, "--estimator", estimator, "--width", str(args.width), "--height",
           str(args.height), "-o", out_exr, "--report", report, "-q"] + extra
    env = dict(os.environ)
    if threads is not None:
        env["LP_NUM_THREADS"] = str(threads)
    return subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def finish(proc, what):
    _, err = proc.communicate()
    if proc.returncode != 0:
        fail(f"{what} failed (exit {proc.returncode}): {err.strip().splitlines()[-1] if err.strip() else 'no message'}")


def write_constant_exr(path, width, height, rgb):
    """An uncompressed FLOAT RGB OpenEXR image with every pixel rgb (an analytic reference: a furnace's)."""
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in "BGR") + b"\0"
    box = struct.pack("<4i", 0, 0, width - 1, height - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", chlist) +
              attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", box) +
              attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attr("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line = b"".join(struct.pack("<f", v) * width for v in (rgb[2], rgb[1], rgb[0]))
    block = 8 + len(line)
    start = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", start + y * block) for y in range(height))
    blocks = b"".join(struct.pack("<ii", y, len(line)) + line for y in range(height))
    with open(path, "wb") as f:
        f.write(header + offsets + blocks)


def reference_for(args, tmp):
    if args.reference_constant is not None:
        path = os.path.join(tmp, "constant_reference.exr")
        write_constant_exr(path, args.width, args.height, [args.reference_constant] * 3)
        return path
    if args.reference:
        if not os.path.isfile(args.reference):
            fail(f"no reference {args.reference}")
        return args.reference
    key = digest(file_bytes(args.scene), file_bytes(args.a), args.width, args.height, args.reference_spp,
                 file_bytes(args.vkmc))
    path = os.path.join(cache_dir(), key + ".exr")
    if os.path.isfile(path):
        return path
    os.makedirs(cache_dir(), exist_ok=True)
    print(f"rendering the reference ({args.reference_spp} spp with {os.path.basename(args.a)}) to {path}",
          file=sys.stderr)
    proc = render(args, args.a, path, os.path.join(tmp, "reference.json"),
                  ["--spp", str(args.reference_spp), "--seed", str(0x5eed)])
    finish(proc, "the reference render")
    return path


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("--a", default=os.path.join(ROOT, "scenes/estimators/baseline.json"))
    p.add_argument("--b", default=os.path.join(ROOT, "scenes/estimators/rr_ears_guard.json"))
    p.add_argument("--seconds", type=float, default=16.0)
    p.add_argument("--pairs", type=int, default=4)
    p.add_argument("--width", type=int, default=96)
    p.add_argument("--height", type=int, default=96)
    p.add_argument("--reference")
    p.add_argument("--reference-spp", type=int, default=8192)
    p.add_argument("--reference-constant", type=float, help="an analytic reference: this radiance in every pixel")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--independent-seeds", action="store_true", help="a seed for each render, not one a pair")
    p.add_argument("--json")
    p.add_argument("--vkmc", default=os.environ.get("VKMC", os.path.join(ROOT, "build/vkmc")))
    args = p.parse_args()
    if not (0 < args.seconds <= 86400) or not (1 <= args.pairs <= 1000):
        fail("--seconds must be in (0, 86400] and --pairs in [1, 1000]")
    for path in (args.scene, args.a, args.b, args.vkmc):
        if not os.path.isfile(path):
            fail(f"no such file: {path}")
    if args.json and os.path.lexists(args.json) and not os.path.isfile(args.json):
        fail(f"{args.json} is not a regular file; not replaced")
    if len(os.sched_getaffinity(0)) < 2:
        fail("needs two cores (one render on each)")

    pairs = []
    with tempfile.TemporaryDirectory(prefix="vkmc-paired-") as tmp:
        reference = reference_for(args, tmp)
        for k in range(args.pairs):
            runs = {}
            procs = []
            seed_a = args.seed + 2 * k
            seed_b = seed_a + (1 if args.independent_seeds else 0)
            # Started in turns, A first on even pairs, so neither always starts first.
            order = (("a", args.a, seed_a), ("b", args.b, seed_b))
            for name, est, seed in (order if k % 2 == 0 else order[::-1]):
                exr, rep = os.path.join(tmp, f"{name}{k}.exr"), os.path.join(tmp, f"{name}{k}.json")
                extra = ["--time-budget", str(args.seconds), "--seed", str(seed), "--reference", reference]
                procs.append((name, rep, render(args, est, exr, rep, extra, threads=1)))
            for name, rep, proc in procs:
                finish(proc, f"pair {k}'s render {name.upper()}")
                with open(rep) as f:
                    r = json.load(f)
                relmse, seconds = r.get("relmse"), r.get("seconds")
                if not relmse or not seconds or relmse <= 0 or seconds <= 0:
                    fail(f"pair {k}'s render {name.upper()} reports no relMSE or time")
                runs[name] = {"seed": r.get("seed"), "spp": r.get("spp_reached"), "seconds": seconds,
                              "relmse": relmse, "efficiency": 1.0 / (relmse * seconds),
                              "nonfinite_samples": r.get("nonfinite_samples", 0)}
            ratio = runs["b"]["efficiency"] / runs["a"]["efficiency"]
            pairs.append({"a": runs["a"], "b": runs["b"], "ratio": ratio})
            print(f"pair {k}: A {runs['a']['spp']} spp relMSE {runs['a']['relmse']:.4g}, "
                  f"B {runs['b']['spp']} spp relMSE {runs['b']['relmse']:.4g}: B/A {ratio:.3f}", flush=True)

    logs = [math.log(pr["ratio"]) for pr in pairs]
    mean = statistics.fmean(logs)
    half = t95(len(logs) - 1) * statistics.stdev(logs) / math.sqrt(len(logs)) if len(logs) > 1 else float("inf")
    median = statistics.median(pr["ratio"] for pr in pairs)
    low, high = math.exp(mean - half), math.exp(mean + half)
    print(f"{os.path.basename(args.scene)}: B/A efficiency, {len(pairs)} concurrent pairs at {args.seconds:g} s: "
          f"geometric mean {math.exp(mean):.3f} (95% {low:.3f}-{high:.3f}), median {median:.3f}")
    if args.json:
        out = {"scene": args.scene, "a": args.a, "b": args.b, "seconds": args.seconds, "width": args.width,
               "height": args.height, "reference": reference, "pairs": pairs, "geometric_mean": math.exp(mean),
               "interval95": [low, high], "median": median}
        tmp_json = args.json + ".tmp"
        with open(tmp_json, "w") as f:
            json.dump(out, f, indent=2)
        os.replace(tmp_json, args.json)


if __name__ == "__main__":
    main()
