#!/usr/bin/env bash
# Frame times of two lenslab builds, interleaved (A B A B …: this machine is shared and noisy), as the
# median of the per-pair ratios B/A. Each build reads the shaders of its own source tree.
# usage: tests/bench/compare_builds.sh BASELINE/lenslab CANDIDATE/lenslab [pairs] -- RENDER-ARGS...
# e.g.   tests/bench/compare_builds.sh ../old/build/lenslab build/lenslab 9 -- --camera assets/rows/camera-dof.json --width 640
set -euo pipefail
a=$(realpath "$1"); b=$(realpath "$2"); shift 2
pairs=7
if [ "${1:-}" != "--" ]; then pairs=$1; shift; fi
[ "${1:-}" = "--" ] || { echo "usage: $0 BASELINE CANDIDATE [pairs] -- RENDER-ARGS..." >&2; exit 2; }
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
run() { "$1" render "${@:2}" --out "$work/out.png" -q; }
run "$a" "$@"; run "$b" "$@"   # warm the page cache and the shader caches alike
ratios=()
for i in $(seq "$pairs"); do
  a0=$(now); run "$a" "$@"; a1=$(now)
  b0=$(now); run "$b" "$@"; b1=$(now)
  r=$(awk -v a0="$a0" -v a1="$a1" -v b0="$b0" -v b1="$b1" 'BEGIN { printf "%.4f", (b1 - b0) / (a1 - a0) }')
  ratios+=("$r")
  awk -v a0="$a0" -v a1="$a1" -v b0="$b0" -v b1="$b1" -v r="$r" -v i="$i" \
    'BEGIN { printf "pair %d: baseline %.3f s, candidate %.3f s, ratio %s\n", i, a1 - a0, b1 - b0, r }'
done
printf '%s\n' "${ratios[@]}" | sort -g | awk '{ v[NR] = $1 } END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "median ratio candidate/baseline: %.4f over %d pairs\n", m, NR }'
