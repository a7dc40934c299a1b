#!/usr/bin/env bash
# What capture saves over a loop of `render` calls: the same 12 frames of the rack focus (320 px,
# 16 aperture samples) by one `capture` and by 12 `render --camera frame.camera.json --seed S`,
# interleaved A B A B (this machine is shared and noisy), and the median of the ratios.
# usage: tests/bench/capture_vs_render.sh [build/lenslab] [pairs]
set -euo pipefail
lenslab=$(realpath "${1:-build/lenslab}")
pairs=${2:-7}
path=$(realpath "$(dirname "$0")/../../assets/rows/rack-focus.json")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
options=(--width 320 --aperture-samples 16)
"$lenslab" capture --path "$path" --out ref/f_%04d.png "${options[@]}" --frames 0:11 -q
/usr/bin/python3 -c 'import json
for l in map(json.loads, open("ref/manifest.jsonl")): print(l["camera"], l["seed"], l["frame"])' >frames.txt
now() { date +%s.%N; }
ratios=()
for i in $(seq "$pairs"); do
  mkdir -p a b
  a0=$(now); "$lenslab" capture --path "$path" --out a/f_%04d.png "${options[@]}" --frames 0:11 -q; a1=$(now)
  b0=$(now)
  while read -r camera seed frame; do
    "$lenslab" render --camera "ref/$camera" --seed "$seed" "${options[@]}" --out "b/f_$frame.png" -q
  done <frames.txt
  b1=$(now)
  rm -rf a b
  ratio=$(awk -v a0="$a0" -v a1="$a1" -v b0="$b0" -v b1="$b1" 'BEGIN { printf "%.2f", (b1 - b0) / (a1 - a0) }')
  ratios+=("$ratio")
  awk -v a0="$a0" -v a1="$a1" -v b0="$b0" -v b1="$b1" -v r="$ratio" \
    'BEGIN { printf "capture %.2f s, 12 renders %.2f s, ratio %s\n", a1 - a0, b1 - b0, r }'
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{ r[NR] = $1 } END { print "median ratio (renders / capture): " r[int((NR + 1) / 2)] }'
