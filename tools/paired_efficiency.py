#!/usr/bin/env python3
"""Equal-time efficiency of estimator B against estimator A by concurrent pairs: each pair renders A and B at the
same time, each `vkmc render` on one lavapipe thread, so that the machine's swings (its neighbours, its slow and
fast minutes) reach both renders of a pair alike. This VM's two cores do not always run at one speed, so the two
renders trade cores every 0.25 s, each pinned to one of them in turn (--cores swap, the default): each spends half
its time on each core. Pinned for good, two renders of one configuration reached 0.75-1.3x each other's samples in
16 s; left to the scheduler (--cores free) veach_mis's read 0.79-1.26, swapped 0.92-1.004 (docs/journal/ears.md, "Renders
that trade cores"). A pair's ratio is efficiency(B) / efficiency(A), efficiency = 1 / (relMSE against the
reference x seconds). The seeds change from pair to pair; a pair's two renders share their seed (common random
numbers: where B's samples are A's, as where `--rr ears` falls back to throughput roulette, their errors cancel in
the ratio and what is left is what B's time bought; --independent-seeds gives each render its own). docs/journal/ears.md,
"Concurrent pairs", says why: rendered one after the other, two renders of the same configuration read 0.74-1.43x
each other on this machine; side by side they read within a few percent.

  python3 tools/paired_efficiency.py SCENE [--a EST.json] [--b EST.json] [--seconds S] [--pairs N]
      [--width W --height H] [--reference EXR | --reference-spp N | --reference-constant L]
      [--independent-seeds] [--cores swap|free] [--a-flags "..."] [--b-flags "..."] [--json OUT] [--vkmc PATH]

--b auto (or --a auto) renders that side with `--estimator auto`. --a-flags and --b-flags add render flags to one side (e.g. --b-flags="--adaptive on": adaptive sampling against
the same estimator without it); the reference is rendered without them.

A and B default to scenes/estimators/baseline.json (throughput roulette) and rr_ears_guard.json (`--rr ears` as
it runs by default); --b the same file as --a is the method's control. Without --reference, a reference is
rendered with A (--reference-spp samples, both threads) and cached in $VKMC_CACHE_DIR/paired (else
~/.cache/vkmc/paired) under the scene, A, the size, the samples and a 2-spp probe render's bytes (not the binary's:
a rebuild that renders A's image bit for bit the same keeps it). Prints each pair and the geometric mean of the
ratios with a 95% interval from their measured spread (Student t on the log-ratios), and the median. Each relMSE
has the reference's own relative variance (its render's mean_relvariance; 0 for an analytic one) taken out: left
in, it would pull every ratio toward 1.
"""
import argparse
import hashlib
import json
import math
import os
import shlex
import statistics
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Two-sided 95% Student t quantiles by degrees of freedom (beyond the table: the normal's 1.96 is close enough).
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228,
       12: 2.179, 15: 2.131, 20: 2.086, 30: 2.042, 40: 2.021, 60: 2.000, 120: 1.980}


def t95(dof):
    keys = sorted(k for k in T95 if k <= dof)
    return T95[keys[-1]]  # the next smaller tabled dof: a slightly wider interval, never a narrower one


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
    # Its messages to a file, not a pipe: a pair is polled (trade_cores), and a full pipe would stop a render.
    err = tempfile.TemporaryFile()
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=err)
    proc.err_file = err
    return proc


def trade_cores(procs, period=0.25):
    """Pins every thread of the pair's two renders to one core each and swaps the cores every `period` seconds
    until both have ended, so that each spends half its time on each core (threads started between two swaps
    inherit their creator's core)."""
    cores = sorted(os.sched_getaffinity(0))[:2]
    flip = 0
    while any(p.poll() is None for p in procs):
        for k, p in enumerate(procs):
            try:
                for tid in os.listdir(f"/proc/{p.pid}/task"):
                    try:
                        os.sched_setaffinity(int(tid), {cores[k ^ flip]})
                    except OSError:
                        pass  # the thread ended meanwhile
            except OSError:
                pass  # the render ended meanwhile
        flip ^= 1
        time.sleep(period)


def finish(proc, what, others=()):
    proc.wait()
    proc.err_file.seek(0)
    err = proc.err_file.read().decode(errors="replace")
    proc.err_file.close()
    if proc.returncode != 0:
        for other in others:  # the pair's other render: not left running into a removed folder
            other.kill()
            other.wait()
        fail(f"{what} failed (exit {proc.returncode}): {err.strip().splitlines()[-1] if err.strip() else 'no message'}")


def number(value):
    return value if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) else None


def read_report(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{what}: no readable report ({e})")


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


def probe_image(args, tmp):
    """A 2-spp render of the scene with A at the reference's size and seed, as bytes: what keys the cached reference
    instead of the vkmc binary, so a rebuild that leaves A's image alone (bit for bit, as a fixed seed renders it)
    keeps its reference, and one that changes it (or the scene's buffers, which the .gltf's bytes leave out) does
    not. An A whose image depends on time (a guard, a budget) misses the cache every time: correct, only slow."""
    exr, report = os.path.join(tmp, "probe.exr"), os.path.join(tmp, "probe.json")
    finish(render(args, args.a, exr, report, ["--spp", "2", "--seed", str(0x5eed)]), "the reference's probe render")
    return file_bytes(exr)


def reference_for(args, tmp):
    """The reference EXR and its own relative variance (what it adds to every relMSE: None where unknown)."""
    if args.reference_constant is not None:
        path = os.path.join(tmp, "constant_reference.exr")
        write_constant_exr(path, args.width, args.height, [args.reference_constant] * 3)
        return path, 0.0
    if args.reference:
        if not os.path.isfile(args.reference):
            fail(f"no reference {args.reference}")
        return args.reference, None
    key = digest(file_bytes(args.scene), file_bytes(args.a), args.width, args.height, args.reference_spp,
                 probe_image(args, tmp))
    path = os.path.join(cache_dir(), key + ".exr")
    report = os.path.join(cache_dir(), key + ".json")  # its report: mean_relvariance is the reference's own noise
    if not (os.path.isfile(path) and os.path.isfile(report)):
        os.makedirs(cache_dir(), exist_ok=True)
        print(f"rendering the reference ({args.reference_spp} spp with {os.path.basename(args.a)}) to {path}",
              file=sys.stderr)
        proc = render(args, args.a, path, report, ["--spp", str(args.reference_spp), "--seed", str(0x5eed)])
        finish(proc, "the reference render")
    return path, number(read_report(report, "the reference render").get("mean_relvariance"))


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
    p.add_argument("--cores", choices=("swap", "free"), default="swap",
                   help="swap: the two renders trade cores every 0.25 s; free: left to the scheduler")
    p.add_argument("--a-flags", default="", help="render flags for A's renders (not the reference's)")
    p.add_argument("--b-flags", default="", help="render flags for B's renders")
    p.add_argument("--json")
    p.add_argument("--vkmc", default=os.environ.get("VKMC", os.path.join(ROOT, "build/vkmc")))
    args = p.parse_args()
    if not (0 < args.seconds <= 86400) or not (1 <= args.pairs <= 1000):
        fail("--seconds must be in (0, 86400] and --pairs in [1, 1000]")
    if not (1 <= args.width <= 8192 and 1 <= args.height <= 8192 and 1 <= args.reference_spp <= 1 << 24):
        fail("--width and --height must be in [1, 8192], --reference-spp in [1, 16777216]")
    if args.reference_constant is not None and not (math.isfinite(args.reference_constant) and args.reference_constant > 0):
        fail("--reference-constant must be a finite radiance above 0")
    for path in (args.scene, args.a, args.b, args.vkmc):
        if path != "auto" and not os.path.isfile(path):  # --a/--b auto: `--estimator auto`
            fail(f"no such file: {path}")
    json_path = os.path.realpath(args.json) if args.json else None  # a symlink keeps pointing at its replaced target
    if json_path and os.path.lexists(json_path) and not os.path.isfile(json_path):
        fail(f"{args.json} is not a regular file; not replaced")
    if len(os.sched_getaffinity(0)) < 2:
        fail("needs two cores (one render on each)")

    pairs = []
    with tempfile.TemporaryDirectory(prefix="vkmc-paired-") as tmp:
        reference, reference_noise = reference_for(args, tmp)
        if reference_noise is None:
            print("paired_efficiency: the reference's own variance is unknown: every relMSE includes it, which pulls "
                  "the ratios toward 1", file=sys.stderr)
        for k in range(args.pairs):
            runs = {}
            procs = []
            seed_a = args.seed + 2 * k
            seed_b = seed_a + (1 if args.independent_seeds else 0)
            # Started in turns, A first on even pairs, so neither always starts first.
            order = (("a", args.a, seed_a, args.a_flags), ("b", args.b, seed_b, args.b_flags))
            for name, est, seed, flags in (order if k % 2 == 0 else order[::-1]):
                exr, rep = os.path.join(tmp, f"{name}{k}.exr"), os.path.join(tmp, f"{name}{k}.json")
                extra = ["--time-budget", str(args.seconds), "--seed", str(seed), "--reference", reference]
                extra += shlex.split(flags)
                procs.append((name, rep, render(args, est, exr, rep, extra, threads=1)))
            if args.cores == "swap":
                trade_cores([p for _, _, p in procs])
            for name, rep, proc in procs:
                what = f"pair {k}'s render {name.upper()}"
                finish(proc, what, [p for _, _, p in procs if p is not proc])
                r = read_report(rep, what)
                relmse, seconds = number(r.get("relmse")), number(r.get("seconds"))
                if not relmse or not seconds or relmse <= 0 or seconds <= 0:
                    fail(f"{what} reports no relMSE or time")
                # The reference's own noise is in every relMSE (independent of the render's); taken out, what is
                # left is the render's own error.
                own = relmse - (reference_noise or 0.0)
                if own <= 0:
                    fail(f"{what}: relMSE {relmse:.4g} is within the reference's own noise {reference_noise:.4g} "
                         "(a longer reference, or a shorter render)")
                nonfinite = number(r.get("nonfinite_samples")) or 0
                if nonfinite:
                    print(f"paired_efficiency: {what} excluded {nonfinite:g} non-finite samples", file=sys.stderr)
                runs[name] = {"seed": r.get("seed"), "spp": r.get("spp_reached"), "seconds": seconds,
                              "relmse": relmse, "relmse_own": own, "efficiency": 1.0 / (own * seconds),
                              "nonfinite_samples": nonfinite}
            ratio = runs["b"]["efficiency"] / runs["a"]["efficiency"]
            pairs.append({"a": runs["a"], "b": runs["b"], "ratio": ratio})
            print(f"pair {k}: A {runs['a']['spp']} spp relMSE {runs['a']['relmse']:.4g}, "
                  f"B {runs['b']['spp']} spp relMSE {runs['b']['relmse']:.4g}: B/A {ratio:.3f}", flush=True)

    logs = [math.log(pr["ratio"]) for pr in pairs]
    mean = statistics.fmean(logs)
    median = statistics.median(pr["ratio"] for pr in pairs)
    interval = None  # one pair: no spread to measure
    if len(logs) > 1:
        half = t95(len(logs) - 1) * statistics.stdev(logs) / math.sqrt(len(logs))
        interval = [math.exp(mean - half), math.exp(mean + half)]
    shown = f"95% {interval[0]:.3f}-{interval[1]:.3f}" if interval else "one pair: no interval"
    print(f"{os.path.basename(args.scene)}: B/A efficiency, {len(pairs)} concurrent pairs at {args.seconds:g} s: "
          f"geometric mean {math.exp(mean):.3f} ({shown}), median {median:.3f}")
    if json_path:
        out = {"scene": args.scene, "a": args.a, "b": args.b, "a_flags": args.a_flags, "b_flags": args.b_flags,
               "seconds": args.seconds, "width": args.width,
               "height": args.height, "reference": reference, "reference_relvariance": reference_noise,
               "independent_seeds": args.independent_seeds, "cores": args.cores, "pairs": pairs,
               "geometric_mean": math.exp(mean), "interval95": interval, "median": median}
        fd, tmp_json = tempfile.mkstemp(prefix=".paired-", dir=os.path.dirname(json_path) or ".")
        try:
            with os.fdopen(fd, "w") as f:
                json.dump(out, f, indent=2)
            os.replace(tmp_json, json_path)
        except BaseException:
            os.unlink(tmp_json)
            raise


if __name__ == "__main__":
    main()
