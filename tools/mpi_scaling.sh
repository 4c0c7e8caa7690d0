#!/usr/bin/env bash
# One render against the same render across MPI ranks on this machine, interleaved round by round: medians of
# the render seconds (rank 0's pass time) and of the whole command's wall time (set-up included), and the ratio.
#   bash tools/mpi_scaling.sh [ROUNDS] [SCENE] [SPP]        (needs vkmc built with MPI: openmpi-bin libopenmpi-dev)
# Configurations: 1 process (lavapipe's default threads = cores), 2 ranks with LP_NUM_THREADS=1 each (one core
# each), 2 ranks with the default threads (oversubscribed).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
scene=${2:-scenes/cornell_box.gltf}
spp=${3:-256}
vkmc=build/vkmc
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cores=$(nproc)
declare -A run=(
  [one_process]="$vkmc"
  [two_ranks_1_thread]="env LP_NUM_THREADS=$((cores / 2 > 0 ? cores / 2 : 1)) mpirun -q --oversubscribe -np 2 -x LP_NUM_THREADS $vkmc"
  [two_ranks_default_threads]="mpirun -q --oversubscribe -np 2 $vkmc"
)
names=(one_process two_ranks_1_thread two_ranks_default_threads)
for ((r = 0; r < rounds; ++r)); do
  for n in "${names[@]}"; do
    start=$(date +%s.%N)
    # The fixed defaults on every side: under mpirun vkmc does not choose its estimator, alone it would.
    ${run[$n]} render "$scene" --spp "$spp" --estimator defaults -q -o "$out/$n.exr" --report "$out/$n-$r.json"
    end=$(date +%s.%N)
    python3 -c "import json,sys; j=json.load(open('$out/$n-$r.json')); print('$n', $r, j['seconds'], $end - $start, j['samples'])" >> "$out/rows"
  done
done
python3 - "$out/rows" <<'PY'
import statistics, sys, collections
rows = collections.defaultdict(list)
for line in open(sys.argv[1]):
    n, r, render, wall, samples = line.split()
    rows[n].append((float(render), float(wall), int(samples)))
base = None
print(f"{'configuration':28s} {'render s (median)':>18s} {'[min-max]':>16s} {'wall s':>8s} {'Msamples/s':>11s} {'vs one':>7s}")
for n, v in rows.items():
    render = statistics.median(x[0] for x in v); wall = statistics.median(x[1] for x in v)
    rate = v[0][2] / render * 1e-6
    base = base or rate
    lo, hi = min(x[0] for x in v), max(x[0] for x in v)
    print(f"{n:28s} {render:18.2f} {f'[{lo:.2f}-{hi:.2f}]':>16s} {wall:8.2f} {rate:11.2f} {rate / base:7.2f}")
PY
