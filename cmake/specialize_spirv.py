#!/usr/bin/env python3
"""Pre-specializes a kernel's SPIR-V at build time for a few feature sets: in each, some specialization constants
become plain constants, spirv-opt folds and strips the code they switch off
(PASSES below), and the variants are written as one
C++ header.

Why: lavapipe turns a module's whole SPIR-V into NIR, and inlines it, before a pipeline's specialization removes
anything, so a kernel pays at pipeline creation for every feature the scene does not use (shade: 0.2 s). A variant
fixed to a common scene's features is 3-5x smaller. The host (render/kernel_variants.h) uses a variant only when
every constant it fixes has that value in the render's specialization; the others stay specialization constants.

usage: specialize_spirv.py --layout layout.h --spirv-opt PATH --kernel NAME
                           --set NAME:SPEC_X=V,SPEC_Y=W [--set ...] kernel_spv.h variants.h
kernel_spv.h is glslang's header (--vn kSpirv_NAME); constants the kernel does not read are left out of its
variants' fixed lists, and variants that come out alike are written once (named after all their sets, "lambertian+glossy").
"""
import argparse
import os
import re
import struct
import subprocess
import sys
import tempfile

OP_DECORATE, OP_SPEC_TRUE, OP_SPEC_FALSE, OP_SPEC = 71, 48, 49, 50
OP_CONST_TRUE, OP_CONST_FALSE, OP_CONST = 41, 42, 43
DECORATION_SPEC_ID = 1
MAGIC = 0x07230203


def fail(message):
    sys.exit(f'specialize_spirv: {message}')


def spec_ids(layout_path):
    ids = {}
    for line in open(layout_path):
        m = re.match(r'\s*#define\s+(SPEC_\w+)\s+(\d+)', line)
        if m:
            ids[m.group(1)] = int(m.group(2))
    return ids


def read_glslang_header(path):
    words = [int(w, 16) for w in re.findall(r'0x[0-9a-fA-F]{8}', open(path).read())]
    if not words or words[0] != MAGIC:
        fail(f'{path} holds no SPIR-V')
    return words


def instructions(words):
    i = 5
    while i < len(words):
        count, opcode = words[i] >> 16, words[i] & 0xffff
        if count == 0 or i + count > len(words):
            fail('malformed SPIR-V')
        yield words[i:i + count], opcode
        i += count


def declared_spec_ids(words):
    """Spec id -> the result id it decorates."""
    return {inst[3]: inst[1] for inst, op in instructions(words)
            if op == OP_DECORATE and len(inst) == 4 and inst[2] == DECORATION_SPEC_ID}


def fix_constants(words, fixed):
    """The module with the spec constants of `fixed` (spec id -> 32-bit value) turned into constants."""
    result_ids = {result: spec for spec, result in declared_spec_ids(words).items() if spec in fixed}
    out = words[:5]
    for inst, op in instructions(words):
        if op == OP_DECORATE and len(inst) == 4 and inst[2] == DECORATION_SPEC_ID and inst[1] in result_ids:
            continue
        if op in (OP_SPEC_TRUE, OP_SPEC_FALSE) and inst[2] in result_ids:
            value = fixed[result_ids[inst[2]]]
            inst = [(len(inst) << 16) | (OP_CONST_TRUE if value else OP_CONST_FALSE)] + inst[1:]
        elif op == OP_SPEC and inst[2] in result_ids:
            if len(inst) != 4:
                fail('only 32-bit specialization constants can be fixed')
            inst = [(4 << 16) | OP_CONST, inst[1], inst[2], fixed[result_ids[inst[2]]]]
        out.extend(inst)
    return out


# Constant propagation and dead-code removal only, twice (after inlining, so branches on the fixed constants fold
# inside callees). spirv-opt -O's other passes made the kernels slower on llvmpipe, which runs every block for all
# lanes: --merge-return (a function with early returns becomes a one-pass loop) took shade to 1.6x its time,
# --scalar-replacement the megakernel to 1.05x. Functions with early returns stay calls; lavapipe inlines them.
_CLEAN = ('--eliminate-local-single-block --eliminate-local-single-store --ssa-rewrite --ccp --eliminate-dead-branches '
          '--merge-blocks --eliminate-dead-code-aggressive --eliminate-dead-functions').split()
PASSES = ['--inline-entry-points-exhaustive'] + _CLEAN + _CLEAN


def run_spirv_opt(spirv_opt, args):
    # Quiet unless it fails: without merge-return the inliner warns about every function it leaves as a call.
    r = subprocess.run([spirv_opt] + args, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout + r.stderr)
        fail(f'spirv-opt failed ({r.returncode})')


def optimize(words, spirv_opt):
    with tempfile.TemporaryDirectory() as tmp:
        paths = [os.path.join(tmp, f'{k}.spv') for k in range(3)]
        with open(paths[0], 'wb') as f:
            f.write(struct.pack(f'<{len(words)}I', *words))
        # Two runs: in one, the other passes ran before the fold and left the new constants' expressions unfolded.
        run_spirv_opt(spirv_opt, ['--fold-spec-const-op-composite', paths[0], '-o', paths[1]])
        run_spirv_opt(spirv_opt, PASSES + [paths[1], '-o', paths[2]])
        data = open(paths[2], 'rb').read()
    return list(struct.unpack(f'<{len(data) // 4}I', data))


def parse_set(text, ids):
    name, _, assignments = text.partition(':')
    if not re.fullmatch(r'[a-z][a-z0-9]*', name):
        fail(f'bad feature-set name "{name}"')
    fixed = {}
    for a in filter(None, assignments.split(',')):
        spec, _, value = a.partition('=')
        if spec not in ids:
            fail(f'{spec} is not a specialization constant id')
        try:
            fixed[ids[spec]] = int(value, 0) & 0xffffffff
        except ValueError:
            fail(f'{spec}={value}: only integer values can be fixed')
    return name, fixed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--layout', required=True)
    ap.add_argument('--spirv-opt', required=True)
    ap.add_argument('--kernel', required=True)
    ap.add_argument('--set', action='append', default=[])
    ap.add_argument('input')
    ap.add_argument('output')
    a = ap.parse_args()
    ids = spec_ids(a.layout)
    words = read_glslang_header(a.input)
    # The constants the kernel reads: glslang declares every one its includes name, -O drops those no code uses.
    declared = declared_spec_ids(optimize(words, a.spirv_opt))
    lines = [f'// Generated by cmake/specialize_spirv.py from {os.path.basename(a.input)}: do not edit.', '#pragma once',
             '#include <cstdint>']
    groups = {}  # the fixed constants this module declares -> the names of the sets that fix them
    for text in a.set:
        name, fixed = parse_set(text, ids)
        key = tuple(sorted((spec, value) for spec, value in fixed.items() if spec in declared))
        if key:
            groups.setdefault(key, []).append(name)
    rows = []
    for index, (key, names) in enumerate(groups.items()):
        var = f'kSpirvVariant_{a.kernel}_{index}'  # never a kernel's own kSpirv_ name
        out = optimize(fix_constants(words, dict(key)), a.spirv_opt)
        lines.append(f'const uint32_t {var}[] = {{')
        lines += ['\t' + ','.join(f'0x{w:08x}' for w in out[k:k + 8]) + ',' for k in range(0, len(out), 8)]
        lines.append('};')
        pairs = ', '.join(f'{{{spec}u, 0x{value:08x}u}}' for spec, value in key)
        lines.append(f'const uint32_t {var}_fixed[][2] = {{{pairs}}};  // (spec id, value)')
        rows.append(f'X("{a.kernel}", "{"+".join(names)}", {var}, {var}_fixed)')
    lines.append(f'#define VKMC_SPIRV_VARIANTS_{a.kernel}(X) ' + ' '.join(rows))
    with open(a.output, 'w') as f:
        f.write('\n'.join(lines) + '\n')


if __name__ == '__main__':
    main()
