#!/usr/bin/env python3
"""Copies a process's anonymous executable mappings (llvmpipe's JIT code: one region per compiled kernel, in
practice) to OUT/region_<start>.bin and lists them in OUT/regions.txt. Usage: dump_jit.py PID OUT."""
import os
import subprocess
import sys


def main():
    pid, out = sys.argv[1], sys.argv[2]
    regions = []
    with open(f"/proc/{pid}/maps") as maps, open(f"/proc/{pid}/mem", "rb") as mem:
        for line in maps:
            fields = line.split()
            if "x" not in fields[1] or len(fields) >= 6:  # executable, and no file or [name] behind it
                continue
            lo, hi = (int(x, 16) for x in fields[0].split("-"))
            mem.seek(lo)
            path = os.path.join(out, f"region_{lo:x}.bin")
            with open(path, "wb") as f:
                f.write(mem.read(hi - lo))
            regions.append((lo, hi))
    with open(os.path.join(out, "regions.txt"), "w") as f:
        for lo, hi in regions:
            f.write(f"{lo:x} {hi:x}\n")
            with open(os.path.join(out, f"region_{lo:x}.asm"), "w") as asm:
                subprocess.run(["objdump", "-D", "-b", "binary", "-m", "i386:x86-64", f"--adjust-vma=0x{lo:x}",
                                os.path.join(out, f"region_{lo:x}.bin")], stdout=asm, check=True)


if __name__ == "__main__":
    main()
