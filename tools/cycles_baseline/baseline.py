#!/usr/bin/env python3
"""vkmc against Blender Cycles (CPU) on one glTF scene: equal spp and equal time, errors against a cached vkmc reference.

Run through tools/cycles_baseline.sh (which installs Blender and builds vkmc). Every number in the table is a median
over --repeats runs with different seeds. Times are the renderers' own sample-loop times: vkmc's report `seconds`
(sample passes only; loading, BVH, upload and pipelines excluded) and Cycles' `cycles.<layer>.render_time` from the
EXR header (rendering without synchronization; Blender's start-up, the glTF import and Cycles' scene sync excluded).
"""
import argparse
import hashlib
import json
import os
import re
import shlex
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VKMC = os.path.join(ROOT, "build", "vkmc")
CYCLES_SCRIPT = os.path.join(ROOT, "tools", "cycles_baseline", "render_cycles.py")
REFERENCE_SEED = 1000003  # never one of the test seeds (1..repeats): a shared seed would correlate the samples


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def run(cmd, **kw):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if p.returncode != 0:
        sys.exit(f"cycles_baseline: failed ({p.returncode}): {' '.join(cmd)}\n{p.stdout[-3000:]}")
    return p.stdout


def vkmc_render(args, out, spp=None, seconds=None, seed=1, ref=False):
    report = out[:-4] + ".json"
    cmd = [VKMC, "render", args.scene, "-o", out, "--report", report, "--width", str(args.width),
           "--height", str(args.height), "--seed", str(seed), "--rr-depth", str(args.rr_depth), "-q",
           "--background", "0,0,0"]  # Cycles' world is black (render_cycles.py): no studio on vkmc's side either
    if not ref:
        cmd += shlex.split(args.vkmc_args)  # the renders compared, never the reference
    if seconds is not None:
        cmd += ["--time-budget", str(seconds), "--spp", str(1 << 24)]
    else:
        cmd += ["--spp", str(spp)]
    run(cmd)
    with open(report) as f:
        r = json.load(f)
    return {"spp": r.get("spp_reached", r["spp"]), "seconds": r["seconds"], "mean": r["mean"],
            "mean_relvariance": r.get("mean_relvariance")}


def exr_header(path):
    text = run(["exrheader", path])
    fields = {}
    for line in text.splitlines():
        m = re.match(r'^(\S+) \(type string\): "(.*)"$', line.strip())
        if m:
            fields[m.group(1)] = m.group(2)
    return fields


def clock_seconds(s):
    # Blender's time strings: "SS.ss", "MM:SS.ss" or "HH:MM:SS.ss".
    total = 0.0
    for part in s.split(":"):
        total = total * 60 + float(part)
    return total


def cycles_render(args, out, spp=None, seconds=None, seed=1):
    cmd = [args.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", CYCLES_SCRIPT, "--", args.scene, out,
           "--width", str(args.width), "--height", str(args.height), "--seed", str(seed),
           "--threads", str(args.threads), "--min-bounces", str(args.min_bounces), "--pattern", args.pattern]
    cmd += ["--time-limit", str(seconds)] if seconds is not None else ["--spp", str(spp)]
    if args.cycles_adaptive > 0:
        cmd += ["--adaptive-threshold", str(args.cycles_adaptive)]
    t0 = time.perf_counter()
    text = run(cmd)
    wall = time.perf_counter() - t0
    h = exr_header(out)
    key = lambda suffix: next(v for k, v in h.items() if k.startswith("cycles.") and k.endswith(suffix))
    # The header's `samples` is the requested count; under a time limit the samples reached are the last
    # progress line's "Sample N/M" (Cycles renders whole-image sample batches, so every pixel has N).
    reached = max(int(n) for n in re.findall(r"\| Sample (\d+)/\d+", text))
    return {"spp": reached, "seconds": clock_seconds(key(".render_time")),
            "sync_seconds": clock_seconds(key(".synchronization_time")), "process_seconds": wall}


def compare(image, reference, heatmap=None):
    out = image[:-4] + ".cmp.json"
    cmd = [VKMC, "compare", image, reference, "--json", out] + (["--heatmap", heatmap] if heatmap else [])
    run(cmd)
    with open(out) as f:
        return json.load(f)


def scene_key(args):
    with open(args.scene, "rb") as f:
        digest = hashlib.sha256(f.read() + b"|black-world").hexdigest()[:12]
    return digest


def reference(args, cache):
    if args.reference:
        return args.reference, None
    name = f"ref-{scene_key(args)}-{args.width}x{args.height}-{args.ref_spp}spp-seed{REFERENCE_SEED}.exr"
    path = os.path.join(cache, name)
    if not os.path.exists(path):
        log(f"reference: vkmc at {args.ref_spp} spp (cached as {path}; the first run takes a while)")
        vkmc_render(args, path, spp=args.ref_spp, seed=REFERENCE_SEED, ref=True)
    with open(path[:-4] + ".json") as f:
        return path, json.load(f)


def cycles_min_bounces(rr_depth):
    # vkmc roulettes the continuation from vertex rr_depth - 1 (the camera's hit is vertex 0): vertex rr_depth's
    # emission, light sample and everything after are at stake. Cycles adds 1 to min_light_bounces (its
    # kernel's min_bounce, "so that a bounce of 0 indicates ... only direct illumination") and roulettes at the hit
    # of vertex k > min_bounce, after adding that hit's emission and before its light sample. The same first
    # rouletted light sample, vertex rr_depth: min_light_bounces = rr_depth - 2 (Cycles keeps one emission more).
    return max(rr_depth - 2, 0)


def median_row(runs):
    keys = runs[0].keys()
    return {k: statistics.median(r[k] for r in runs) for k in keys if isinstance(runs[0][k], (int, float))}


def measure(args, ref, work):
    # Renderers interleaved run by run (vkmc, Cycles, vkmc, ...) so that load from other processes hits both alike.
    ladder = [("spp", n) for n in args.spp] + [("time", s) for s in args.seconds]
    runs = {(renderer, rung): [] for renderer in ("vkmc", "cycles") for rung in ladder}
    for mode, value in ladder:
        for r in range(args.repeats):
            seed = 1 + r
            for renderer, render in (("vkmc", vkmc_render), ("cycles", cycles_render)):
                out = os.path.join(work, f"{renderer}-{mode}{value}-seed{seed}.exr")
                res = render(args, out, spp=value, seed=seed) if mode == "spp" else render(args, out, seconds=value, seed=seed)
                metrics = compare(out, ref, out[:-4] + ".heat.exr")
                res["relmse"] = metrics["relmse"]
                res["mean_difference"] = metrics["mean_difference"]
                res["relmse_x_spp"] = res["relmse"] * res["spp"]
                res["efficiency"] = 1.0 / (res["relmse"] * res["seconds"]) if res["relmse"] > 0 and res["seconds"] > 0 else 0.0
                runs[(renderer, (mode, value))].append(res)
                log(f"{renderer:6s} {mode}={value}: seed {seed}: {res['spp']} spp, {res['seconds']:.3f} s, relMSE {res['relmse']:.4g}")
    rows = []
    for renderer in ("vkmc", "cycles"):
        for mode, value in ladder:
            row = median_row(runs[(renderer, (mode, value))])
            row.update(renderer=renderer, mode=mode, target=value, runs=runs[(renderer, (mode, value))])
            rows.append(row)
    return rows


def spread(runs, key):
    values = [r[key] for r in runs]
    m = statistics.median(values)
    return (max(values) - min(values)) / m if len(values) > 1 and m else 0.0


def print_table(args, rows, ref_path, ref_report):
    print(f"scene {args.scene}  {args.width}x{args.height}  repeats {args.repeats} (medians; seeds 1..{args.repeats})")
    if ref_report:
        print(f"reference {ref_path}: vkmc {ref_report['spp']} spp, mean {[round(m, 5) for m in ref_report['mean']]}, "
              f"its own expected relMSE {ref_report.get('mean_relvariance', float('nan')):.3g} (included in every relMSE below)")
    else:
        print(f"reference {ref_path}")
    if args.vkmc_args:
        print(f"vkmc's renders also take: {args.vkmc_args}")
    if args.cycles_adaptive > 0:
        print(f"Cycles' renders use adaptive sampling at noise threshold {args.cycles_adaptive}")
    print(f"roulette: vkmc --rr-depth {args.rr_depth}, Cycles min_light_bounces {args.min_bounces} (its first rouletted "
          f"light sample at vertex {args.min_bounces + 2}; vkmc's at vertex {max(args.rr_depth, 1)}; the camera's hit is "
          f"vertex 0)")
    print("seconds: sample loop only (vkmc report 'seconds'; Cycles render_time without sync, from its EXR header); "
          "relMSE spread: (max - min)/median over the repeats; mean - ref mean: image mean minus the reference's, "
          "over pixels and channels, relative")
    print()
    ref_mean = statistics.mean(ref_report["mean"]) if ref_report else float("nan")
    ref_noise = ref_report.get("mean_relvariance", 0.0) if ref_report else 0.0
    print("| renderer | mode | spp | seconds | relMSE | relMSE x spp | (relMSE - ref's) x spp | efficiency 1/(relMSE x s) "
          "| relMSE spread | mean - ref mean |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        target = f"{r['target']} spp" if r["mode"] == "spp" else f"{r['target']} s"
        print(f"| {r['renderer']} | {target} | {r['spp']:.0f} | {r['seconds']:.3f} | {r['relmse']:.4g} | "
              f"{r['relmse_x_spp']:.4g} | {(r['relmse'] - ref_noise) * r['spp']:.4g} | {r['efficiency']:.4g} | {spread(r['runs'], 'relmse'):.0%} | "
              f"{r['mean_difference'] / ref_mean:+.2%} |")
    print()
    by = {(r["renderer"], r["mode"], r["target"]): r for r in rows}
    for n in args.spp:
        v, c = by[("vkmc", "spp", n)], by[("cycles", "spp", n)]
        print(f"equal spp {n}: relMSE x spp vkmc/Cycles = {v['relmse_x_spp'] / c['relmse_x_spp']:.3f}, "
              f"seconds per spp vkmc/Cycles = {(v['seconds'] / v['spp']) / (c['seconds'] / c['spp']):.3f}")
    for s in args.seconds:
        v, c = by[("vkmc", "time", s)], by[("cycles", "time", s)]
        print(f"equal time {s} s: efficiency vkmc/Cycles = {v['efficiency'] / c['efficiency']:.3f} "
              f"(relMSE vkmc/Cycles = {v['relmse'] / c['relmse']:.3f}; spp {v['spp']:.0f} vs {c['spp']:.0f})")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene")
    p.add_argument("seconds", nargs="?", type=float, default=20.0, help="equal-time budget (default 20)")
    p.add_argument("--width", type=int, default=256)
    p.add_argument("--height", type=int, default=256)
    p.add_argument("--spp", type=int, nargs="*", default=[1, 4, 16, 64], help="equal-spp ladder")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--ref-spp", type=int, default=4096)
    p.add_argument("--reference", help="use this EXR as the reference instead of rendering one")
    p.add_argument("--threads", type=int, default=2, help="Cycles' threads (vkmc: lavapipe's, LP_NUM_THREADS)")
    p.add_argument("--rr-depth", type=int, default=3, help="vkmc's --rr-depth (its default 3); sets Cycles' min bounces")
    p.add_argument("--min-bounces", type=int, help="Cycles' min_light_bounces (default: --rr-depth - 2, the same first "
                   "rouletted light sample; see cycles_min_bounces)")
    p.add_argument("--pattern", default="PROGRESSIVE_MULTI_JITTER", help="Cycles' sampling pattern (or SOBOL)")
    p.add_argument("--vkmc-args", default="", help="more options for vkmc's compared renders (not the reference), "
                   "e.g. \"--replicates 1 --light-sampling solid-angle\"")
    p.add_argument("--cycles-adaptive", type=float, default=0.0, metavar="THRESHOLD",
                   help="Cycles' adaptive sampling at this noise threshold (e.g. 0.01; 0: off), to set beside vkmc's "
                   "--adaptive on (--vkmc-args)")
    p.add_argument("--blender", default="blender")
    p.add_argument("--out", help="folder for the renders (default build/cycles_baseline/<scene>-<hash>)")
    p.add_argument("--json", help="write every run as JSON")
    args = p.parse_args()
    if args.min_bounces is None:
        args.min_bounces = cycles_min_bounces(args.rr_depth)
        if args.rr_depth < 2:
            log(f"cycles_baseline: warning: Cycles roulettes no light sample before vertex 2; vkmc's --rr-depth "
                f"{args.rr_depth} starts earlier, so the two starts differ")
    args.scene = os.path.abspath(args.scene)
    args.seconds = [args.seconds] if args.seconds > 0 else []
    cache = os.path.join(ROOT, "build", "cycles_baseline")
    stem = os.path.splitext(os.path.basename(args.scene))[0]
    work = args.out or os.path.join(cache, f"{stem}-{scene_key(args)}-{args.width}x{args.height}")
    os.makedirs(work, exist_ok=True)
    ref_path, ref_report = reference(args, cache)
    rows = measure(args, ref_path, work)
    print_table(args, rows, ref_path, ref_report)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"scene": args.scene, "width": args.width, "height": args.height, "reference": ref_path,
                       "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
