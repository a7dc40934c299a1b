#!/usr/bin/env bash
# Frame times of two renders by one lenslab build, interleaved (A B A B …: this machine is shared and
# noisy), as the median of the per-pair ratios B/A, with each render's own seconds (lenslab's
# --stats "seconds": the frame without the process's start).
# usage: tests/bench/compare_renders.sh LENSLAB [pairs] -- A-RENDER-ARGS... -vs- B-RENDER-ARGS...
# e.g.   tests/bench/compare_renders.sh build/lenslab 7 -- assets/occluder/occluder.gltf --camera \
#          assets/occluder/camera-dof.json --width 480 --aperture-samples 32 -vs- assets/occluder/occluder.gltf \
#          --camera assets/occluder/camera-dof.json --width 480 --aperture-samples 16 --cell-filter on
set -euo pipefail
lenslab=$(realpath "$1"); shift
pairs=7
if [ "${1:-}" != "--" ]; then pairs=$1; shift; fi
[ "${1:-}" = "--" ] || { echo "usage: $0 LENSLAB [pairs] -- A-ARGS... -vs- B-ARGS..." >&2; exit 2; }
shift
a=(); b=(); side=a
for arg in "$@"; do
  if [ "$arg" = "-vs-" ]; then side=b; continue; fi
  if [ $side = a ]; then a+=("$arg"); else b+=("$arg"); fi
done
[ ${#b[@]} -gt 0 ] || { echo "$0: give the second render's arguments after -vs-" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seconds() {  # one render; prints its frame seconds
  "$lenslab" render "$@" --out "$work/out.exr" -q --stats "$work/stats.json"
  python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['seconds'])" "$work/stats.json"
}
seconds "${a[@]}" > /dev/null; seconds "${b[@]}" > /dev/null  # warm the caches alike
ratios=()
for i in $(seq "$pairs"); do
  ta=$(seconds "${a[@]}"); tb=$(seconds "${b[@]}")
  r=$(awk -v a="$ta" -v b="$tb" 'BEGIN { printf "%.4f", b / a }')
  ratios+=("$r")
  echo "pair $i: A $ta s, B $tb s, ratio B/A $r"
done
printf '%s\n' "${ratios[@]}" | sort -g | awk '{ v[NR] = $1 } END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "median ratio B/A: %.4f over %d pairs\n", m, NR }'
