#!/usr/bin/env bash
# How far the stability table's figures move between SIMD code paths on this machine: runs
# lenslab_stability (the default rows) once per forced path (llvmpipe's CPU caps and vector width,
# Embree's ISA, glibc's libm variants), checks each run against docs/stability.md with --check-doc,
# and prints every row whose figures differ between paths with the range they span.
# docs/stability.md's "How the table holds across CPUs" is this output.
# usage: tests/stability/simd_spread.sh [build-dir]   (default: build; about 15 s a path on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
nofma='GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA,-AVX512F,-AVX'
# name, then the environment that forces the path ("-" for none).
paths=(
  "this-cpu -"
  "llvmpipe-128-bit LP_NATIVE_VECTOR_WIDTH=128"
  "llvmpipe-avx GALLIUM_OVERRIDE_CPU_CAPS=avx"
  "llvmpipe-sse4.1 GALLIUM_OVERRIDE_CPU_CAPS=sse4.1"
  "llvmpipe-sse2 GALLIUM_OVERRIDE_CPU_CAPS=sse2"
  "llvmpipe-nosse GALLIUM_NOSSE=1"
  "embree-sse2 LENSLAB_EMBREE_CONFIG=isa=sse2"
  "embree-sse4.2 LENSLAB_EMBREE_CONFIG=isa=sse4.2"
  "embree-avx LENSLAB_EMBREE_CONFIG=isa=avx"
  "embree-avx2 LENSLAB_EMBREE_CONFIG=isa=avx2"
  "libm-no-fma $nofma"
  "all-sse2 GALLIUM_OVERRIDE_CPU_CAPS=sse2 LENSLAB_EMBREE_CONFIG=isa=sse2 $nofma"
)
status=0
for p in "${paths[@]}"; do
  read -r name vars <<<"$p"
  [ "$vars" = "-" ] && vars=
  # shellcheck disable=SC2086  # the variables are words on purpose
  if env $vars "$build/tests/lenslab_stability" --markdown "$out/$name.md" --check-doc docs/stability.md >"$out/$name.log" 2>&1; then
    result=passes
  else
    result=FAILS
    status=1
  fi
  echo "$name: $(grep -m1 '^GL:' "$out/$name.log" || true); the doc check $result"
  [ "$result" = passes ] || grep -v '^\[ ok' "$out/$name.log" | sed 's/^/    /'
done
python3 - "$out" "${paths[@]%% *}" <<'PY'
import math, re, sys
out, names = sys.argv[1], sys.argv[2:]
tables = {}
for n in names:
    try:
        lines = open(f"{out}/{n}.md").read().splitlines()[2:]
    except FileNotFoundError:
        continue
    tables[n] = [[c.strip() for c in l.strip().strip("|").split(" | ")] for l in lines]
base = tables.get(names[0], [])
group = ""
figure = re.compile(r"identical|-?\d+(?:\.\d+)?(?:e[-+]\d+)?(?= dB|$)")
moved = 0
for i, row in enumerate(base):
    group = row[0] or group
    cells = [t[i][3] for t in tables.values() if i < len(t)]
    if len(set(cells)) == 1:
        continue
    moved += 1
    columns = list(zip(*[figure.findall(c) for c in cells]))
    spans = []
    for col in columns:
        vals = sorted(set(col), key=lambda v: math.inf if v == "identical" else float(v))
        spans.append(vals[0] if len(vals) == 1 else f"{vals[0]} … {vals[-1]}")
    print(f"| {group} | {row[1]} | {'; '.join(spans)} |")
print(f"{moved} of {len(base)} rows differ between the {len(tables)} paths")
PY
exit "$status"
