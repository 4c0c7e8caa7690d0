#!/usr/bin/env python3
"""Where two renderers' errors differ: per-region relMSE from `vkmc compare --heatmap` maps (channel Y is the
per-pixel relMSE, averaged over R, G, B). Usage:
  error_regions.py REFERENCE.exr --a NAME HEAT.exr [HEAT.exr ...] --b NAME HEAT.exr [...]
Heatmaps given for one renderer (several seeds at the same spp) are averaged. Regions come from the reference:
black (nothing seen), the emitter, edges (a 4-neighbour differs by over 25% in luminance: silhouettes and shadow
boundaries), red and green walls, and white surfaces split at their median luminance into lit and dim (dim:
mostly indirect light and penumbrae)."""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exr_read import read_exr  # noqa: E402


def luminance(r, g, b):
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def regions(ref_path):
    w, h, ch = read_exr(ref_path)
    R, G, B = ch["R"], ch["G"], ch["B"]
    L = [luminance(R[i], G[i], B[i]) for i in range(w * h)]
    label = [""] * (w * h)
    white = []
    for y in range(h):
        for x in range(w):
            i = y * w + x
            l = L[i]
            edge = False
            for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                if 0 <= x + dx < w and 0 <= y + dy < h:
                    n = L[(y + dy) * w + x + dx]
                    edge |= abs(l - n) > 0.25 * max(l, n) + 0.01
            if l < 1e-3:
                label[i] = "black"
            elif l > 3.0:
                label[i] = "emitter"
            elif edge:
                label[i] = "edges"
            elif R[i] > 2.5 * G[i]:
                label[i] = "red wall"
            elif G[i] > 1.8 * R[i]:
                label[i] = "green wall"
            else:
                white.append(i)
    median = sorted(L[i] for i in white)[len(white) // 2] if white else 0
    for i in white:
        label[i] = "white lit" if L[i] >= median else "white dim"
    return w, h, label


def mean_heat(paths, n):
    acc = [0.0] * n
    for p in paths:
        _, _, ch = read_exr(p)
        Y = ch["Y"]
        for i in range(n):
            acc[i] += Y[i] / len(paths)
    return acc


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("reference")
    p.add_argument("--a", nargs="+", required=True, metavar=("NAME", "HEAT"))
    p.add_argument("--b", nargs="+", required=True, metavar=("NAME", "HEAT"))
    args = p.parse_args()
    w, h, label = regions(args.reference)
    n = w * h
    a, b = mean_heat(args.a[1:], n), mean_heat(args.b[1:], n)
    names = ["emitter", "edges", "red wall", "green wall", "white lit", "white dim", "black"]
    total_a, total_b = sum(a) / n, sum(b) / n
    print(f"| region | pixels | relMSE {args.a[0]} | relMSE {args.b[0]} | ratio | share of {args.a[0]}'s "
          f"excess |")
    print("|---|---:|---:|---:|---:|---:|")
    for name in names + ["all"]:
        idx = [i for i in range(n) if label[i] == name or name == "all"]
        if not idx:
            continue
        ra, rb = sum(a[i] for i in idx) / len(idx), sum(b[i] for i in idx) / len(idx)
        excess = (sum(a[i] for i in idx) - sum(b[i] for i in idx)) / n
        share = excess / (total_a - total_b) if total_a != total_b else 0.0
        print(f"| {name} | {len(idx) / n:.1%} | {ra:.4g} | {rb:.4g} | {ra / rb if rb else float('nan'):.3f} | "
              f"{share:.0%} |")


if __name__ == "__main__":
    main()
