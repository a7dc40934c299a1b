#!/usr/bin/env bash
# A lens render's memory is bounded by its tiles, not by its frame: a 3000-pixel render through
# every lens effect (distortion, lateral and axial colour, field curvature), which one render
# target could hold, holds at most 900 MB more than a 64-pixel one (its frame alone would take
# about 1.1 GB more: view layers, lens tables and sums at the frame's size). It reports its tiles and
# its lens tables as it goes, and the image is whole.
# usage: memory_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
export LENSLAB_ASSET_DIR="$src/assets"

# Peak resident memory (kB) of one lenslab run, from the kernel's accounting of the child. The
# address-space cap keeps a regression from taking the machine's memory; AddressSanitizer's shadow
# memory alone is past any such cap, so it is left out there (and the bound, which its
# bookkeeping would break, is not checked).
asan=0
grep -q __asan_init "$lenslab" && asan=1
peak_kb() {
  (
    [ "$asan" = 1 ] || ulimit -v 6000000
    python3 -c 'import resource, subprocess, sys
rc = subprocess.run(sys.argv[1:]).returncode
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss if rc == 0 else -rc)' "$@"
  )
}

lens=(render --camera "$src/assets/rows/camera-lens.json" --aperture-samples 2)
small=$(peak_kb "$lenslab" "${lens[@]}" --width 63 -q --out "$work/small.exr")
big=$(LENSLAB_PROGRESS_SECONDS=0 peak_kb "$lenslab" "${lens[@]}" --width 3000 --out "$work/big.exr" \
  --stats "$work/big.json" 2>"$work/stderr")
if [ "$small" -le 0 ] || [ "$big" -le 0 ]; then
  fail "lens renders failed (exit $small, $big): $(tail -3 "$work/stderr")"
else
  echo "peak resident memory: 63 px $((small / 1024)) MiB, 3000 px $((big / 1024)) MiB"
  if [ "$asan" = 1 ]; then
    echo "SKIP: memory bound: this lenslab is built with AddressSanitizer"
  elif [ $((big - small)) -le 900000 ]; then
    pass
  else
    fail "3000-px lens render: $(((big - small) / 1024)) MiB more than a 63-px one (bound 900 MB)"
  fi
  if grep -qF 'a tile may hold' "$work/big.json"; then pass; else fail "3000-px lens render not tiled for memory: $(grep -F tiles "$work/big.json")"; fi
  # Progress through the tiles and through each tile's lens tables.
  if grep -qE 'samples over [0-9]+ tiles.*; tile 1 of [0-9]+: inverse lens table' "$work/stderr" &&
    grep -qE 'tile [2-9] of [0-9]+: forward lens table' "$work/stderr"; then
    pass
  else
    fail "no progress on the tiles' lens tables: $(head -5 "$work/stderr")"
  fi
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
