#!/usr/bin/env python3
"""The largest loops of each JIT region that dump_jit.py wrote (OUT/region_*.asm): per loop its instructions,
stack-frame references (spills and reloads) and selects (blends), and the whole region's size. A loop is the span
of a backward jump; the walk's loop in a trace kernel is its region's longest. Usage: loops.py OUT [--top N].
Counts, unlike the clock, do not move with this shared machine's load (docs/journal/performance.md, "Traversal against
Embree")."""
import bisect
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report import instructions  # noqa: E402  (the same objdump parsing as the profile's report)


def read(path):
    return [(a, text.split(None, 1)[0], text.split(None, 1)[1] if " " in text else "") for a, text in instructions(path)]


def loops(ins):
    addrs = [a for a, _, _ in ins]
    found = []
    for i, (a, mnemonic, operands) in enumerate(ins):
        target = re.match(r"(?:0x)?([0-9a-f]+)", operands.strip()) if mnemonic.startswith("j") else None
        if target and int(target.group(1), 16) < a:
            body = ins[bisect.bisect_left(addrs, int(target.group(1), 16)):i + 1]
            stack = sum(1 for _, _, op in body if "(%rsp" in op or "(%rbp" in op)
            blends = sum(1 for _, mn, _ in body if "blend" in mn)
            found.append((len(body), body[0][0], a, stack, blends))
    return sorted(found, reverse=True)


def main():
    out = sys.argv[1]
    top = int(sys.argv[sys.argv.index("--top") + 1]) if "--top" in sys.argv else 2
    rows = []
    for path in glob.glob(os.path.join(out, "region_*.asm")):
        ins = read(path)
        for n, lo, hi, stack, blends in loops(ins)[:top]:
            rows.append((n, os.path.basename(path), lo, hi, stack, blends, len(ins)))
    print(f"{'loop':>6} {'stack refs':>10} {'blends':>6} {'region':>7}  file, span")
    for n, name, lo, hi, stack, blends, size in sorted(rows, reverse=True)[:12]:
        print(f"{n:6d} {stack:10d} {blends:6d} {size:7d}  {name} {lo:x}-{hi:x}")


if __name__ == "__main__":
    main()
