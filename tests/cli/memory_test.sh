#!/usr/bin/env bash
# A lens render's memory is bounded by its tiles, not by its frame: a 3000-pixel render through
# every lens effect (distortion, lateral and axial colour, field curvature), which one render
# target could hold, holds at most 900 MB more than a 64-pixel one (its frame alone would take
# about 1.1 GB more: view layers, lens tables and sums at the frame's size). It reports its tiles and
# its lens tables as it goes, and the image is whole. And low address-space limits end in one line.
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

# Under any ulimit -v from 500 MB to 1.5 GB each command gives its result or one line and a non-zero
# exit, with nothing left behind: no uncaught exception, no crash, no hint to install what is
# installed. (Below about 460 MB a library's own start-up fails before lenslab's first line runs:
# the loader cannot map a library, or log4cplus, a dependency of a dependency, cannot start its
# threads. Nothing of lenslab's can answer there.) Not under AddressSanitizer: its shadow memory
# alone is past these limits.
if [ "$asan" = 0 ]; then
  walk=(
    "render --width 48"
    "raycast --width 48 --spp 1"
    "capture --path $src/assets/rows/rack-focus.json --frames 0:1 --width 32"
  )
  for mb in 500 700 900 1100 1300 1500; do
    for cmd in "${walk[@]}" "lens"; do
      rm -rf "$work/walk" && mkdir -p "$work/walk"
      out=$work/walk/x.png
      case "$cmd" in capture*) out=$work/walk/f_%04d.png ;; esac
      # shellcheck disable=SC2086  # the command's words
      if [ "$cmd" = lens ]; then
        (ulimit -v $((mb * 1024)) && timeout 120 "$lenslab" lens "$src/assets/lenses/double-gauss-50mm.lens") >/dev/null 2>"$work/walk.err"
      else
        (ulimit -v $((mb * 1024)) && timeout 120 "$lenslab" $cmd -q --out "$out") >/dev/null 2>"$work/walk.err"
      fi
      rc=$?
      lines=$(grep -vc 'warning' "$work/walk.err")
      left=$(find "$work/walk" -type f | wc -l)
      if [ "$rc" -eq 0 ] && [ "$lines" -eq 0 ]; then
        pass
      elif [ "$rc" -ge 1 ] && [ "$rc" -le 2 ] && [ "$lines" -eq 1 ] && [ "$left" -eq 0 ] &&
        grep -q '^lenslab: error: ' "$work/walk.err" && ! grep -q 'install' "$work/walk.err"; then
        pass
      else
        fail "ulimit -v ${mb} MB, $cmd: exit $rc, $lines lines, $left files left: $(head -c 300 "$work/walk.err")"
      fi
    done
  done
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
