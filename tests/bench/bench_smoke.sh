#!/usr/bin/env bash
# Keeps the big-scene benchmark from rotting: tools/make-big-scene.py writes a (small) scene, and
# lenslab_ratios and lenslab_bench each run one short case on it. Timings are printed, not checked.
# Usage: bench_smoke.sh SOURCE_DIR RATIOS_BINARY BENCH_BINARY WORK_DIR
set -euo pipefail
source_dir=$1 ratios=$2 bench=$3 work=$4
rm -rf "$work"
/usr/bin/python3 "$source_dir/tools/make-big-scene.py" "$work" --triangles 100000
common=(--scene "$work/big.gltf" --camera "$work/camera-dof.json" --size 320x180 --views 4)
"$ratios" "${common[@]}" --only accumulation --pairs 1 | tee "$work/ratios.txt"
grep -q "triangles/s" "$work/ratios.txt"
"$bench" "${common[@]}" --benchmark_filter='BM_Accumulate/4/' | tee "$work/bench.txt"
grep -q "triangles_per_s" "$work/bench.txt"
# A bad option is refused in one line naming it.
if "$ratios" --size 0x5 2> "$work/refused.txt"; then echo "--size 0x5 was taken" >&2; exit 1; fi
grep -q -- "--size 0x5" "$work/refused.txt"
