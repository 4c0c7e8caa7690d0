#!/usr/bin/env python3
"""How often `--target-error E` delivers: renders SCENE with --target-error E under N seeds and counts the renders
whose relMSE against a reference, its own noise taken out, is at or under E (the target promises a one-sided 95%
bound, so about 95% should be). Each render runs on its own lavapipe thread, two at a time.

  python3 tools/target_error_check.py SCENE --reference EXR --reference-report JSON --errors 1e-2,1e-3
      [--seeds 20] [--width W --height H] [--flags "..."] [--json OUT] [--vkmc PATH]

The reference is an EXR of the same size; its report's mean_relvariance is its own noise (the paired_efficiency.py
cache holds both: ~/.cache/vkmc/paired/KEY.exr and KEY.json). Prints one line per target: hits, the fraction,
the median relMSE over the target, and the median samples a pixel.
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def render(args, error, seed, tmp):
    exr, report = os.path.join(tmp, f"r{seed}.exr"), os.path.join(tmp, f"r{seed}.json")
    cmd = [args.vkmc, "render", args.scene, "--width", str(args.width), "--height", str(args.height), "--target-error",
           str(error), "--seed", str(seed), "--reference", args.reference, "-o", exr, "--report", report, "-q"]
    cmd += shlex.split(args.flags)
    env = dict(os.environ, LP_NUM_THREADS="1")
    return subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE), report


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("--reference", required=True)
    p.add_argument("--reference-report", required=True)
    p.add_argument("--errors", default="1e-2,1e-3")
    p.add_argument("--seeds", type=int, default=20)
    p.add_argument("--width", type=int, default=192)
    p.add_argument("--height", type=int, default=192)
    p.add_argument("--flags", default="", help="more render flags (e.g. \"--adaptive on\")")
    p.add_argument("--json")
    p.add_argument("--vkmc", default=os.environ.get("VKMC", os.path.join(ROOT, "build/vkmc")))
    args = p.parse_args()
    with open(args.reference_report) as f:
        noise = float(json.load(f)["mean_relvariance"])
    results = {}
    with tempfile.TemporaryDirectory(prefix="vkmc-target-") as tmp:
        for error in (float(e) for e in args.errors.split(",")):
            runs = []
            seeds = list(range(1, args.seeds + 1))
            for k in range(0, len(seeds), 2):  # two at a time, one thread each
                procs = [render(args, error, s, tmp) for s in seeds[k:k + 2]]
                for proc, report in procs:
                    _, err = proc.communicate()
                    if proc.returncode != 0:
                        sys.exit(f"target_error_check: a render failed: {err.decode(errors='replace').strip()}")
                    with open(report) as f:
                        r = json.load(f)
                    runs.append({"relmse_own": r["relmse"] - noise, "spp": r["spp"], "seconds": r["seconds"],
                                 "reached": r["sample_rounds"].get("target_reached", False)})
            hits = sum(run["relmse_own"] <= error for run in runs)
            ratio = statistics.median(run["relmse_own"] / error for run in runs)
            spp = statistics.median(run["spp"] for run in runs)
            print(f"{os.path.basename(args.scene)} target {error:g}: {hits}/{len(runs)} at or under it "
                  f"({hits / len(runs):.0%}), median relMSE/target {ratio:.2f}, median {spp:g} spp, "
                  f"reference noise {noise:.3g}", flush=True)
            results[str(error)] = {"hits": hits, "renders": len(runs), "runs": runs}
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"scene": args.scene, "flags": args.flags, "reference": args.reference, "results": results}, f,
                      indent=2)


if __name__ == "__main__":
    main()
