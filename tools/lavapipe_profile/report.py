#!/usr/bin/env python3
"""Per JIT region (a compiled kernel): its share of perf's samples, and the share of its samples inside
llvmpipe's per-lane loops (`inc; cmp $LANES; jae`, LANES 4, 8 or 16 by LP_NATIVE_VECTOR_WIDTH, around a body that extracts one lane's address from a spilled
vector, checks it against the buffer's size and loads or stores): the price of storage-buffer accesses. Lists a
region's costliest such loops with their length (instructions per lane) and whether they store.
Usage: report.py OUT (as written by lavapipe_profile.sh)."""
import collections
import os
import re
import sys

# objdump -D: "addr:<TAB>bytes<TAB>mnemonic operands"; an instruction of more than 7 bytes continues on a line of
# bytes alone (no second tab), which is not an instruction.
INSTRUCTION = re.compile(r"\s*([0-9a-f]+):\t[0-9a-f ]+\t(.+)")
STORE = re.compile(r",\s*(0x[0-9a-f]+)?\(%r(?!sp)\w+(,%r\w+,\d)?\)$")  # a store through a pointer, not the stack


def instructions(path):
    result = []
    with open(path) as f:
        for line in f:
            m = INSTRUCTION.match(line)
            if m:
                result.append((int(m.group(1), 16), m.group(2).strip()))
    return result


def lane_loops(code):
    loops = []
    for i in range(1, len(code) - 1):
        if re.match(r"cmp\s+\$0x(4|8|10),%e", code[i][1]):  # 4, 8 or 16 lanes
            m = re.match(r"jae\s+0x([0-9a-f]+)", code[i + 1][1])
            if m:
                end = int(m.group(1), 16)
                body = [t for a, t in code[i + 2:] if a < end]
                loops.append((code[i - 1][0], end, len(body), any(STORE.search(t) for t in body)))
    return loops


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "samples.txt")) as f:
        ips = [int(x, 16) for x in f.read().split()]
    total = len(ips)
    with open(os.path.join(out, "regions.txt")) as f:
        regions = [tuple(int(x, 16) for x in line.split()) for line in f]
    per_region = collections.defaultdict(collections.Counter)
    outside = 0
    for ip in ips:
        for lo, hi in regions:
            if lo <= ip < hi:
                per_region[lo][ip] += 1
                break
        else:
            outside += 1
    print(f"{total} samples; {100 * outside / max(total, 1):.1f}% outside the JIT code (driver, kernel, host)")
    for lo, counts in sorted(per_region.items(), key=lambda kv: -sum(kv[1].values())):
        n = sum(counts.values())
        if n < 0.01 * total:
            continue
        code = instructions(os.path.join(out, f"region_{lo:x}.asm"))
        loops = lane_loops(code)
        costs = [(sum(c for ip, c in counts.items() if s <= ip < e), s, length, store) for s, e, length, store in loops]
        in_loops = sum(c[0] for c in costs)
        print(f"region {lo:x}: {100 * n / total:.1f}% of samples, {len(code)} instructions, {len(loops)} lane loops "
              f"holding {100 * in_loops / n:.1f}% of its samples")
        for cost, start, length, store in sorted(costs, reverse=True)[:6]:
            if cost:
                print(f"    {100 * cost / n:5.1f}%  loop at {start:x}: {length} instructions a lane, "
                      f"{'store' if store else 'load'}")


if __name__ == "__main__":
    main()
