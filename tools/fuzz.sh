#!/usr/bin/env bash
# Fuzzes the glTF loader and the camera JSON reader with libFuzzer for a bounded time each.
# usage: tools/fuzz.sh [SECONDS] [TARGET...]      SECONDS per target (default 60);
#        TARGET: gltf_loader_fuzz, camera_json_fuzz (default both, one after the other)
# Builds the fuzz preset (clang-14; CMakePresets.json), copies the committed seed corpus
# (fuzz/corpus/<kind>) to a scratch folder so that the committed one is never written to, runs
# each target with -max_total_time=SECONDS -timeout=10 -rss_limit_mb=2048 and its dictionary, and
# prints per target: executions, executions per second, corpus size, findings.
# A finding (crash, abort, uncaught exception other than InputError, sanitizer report, timeout,
# out-of-memory) is kept as build-fuzz/runs/<target>/artifacts/<kind>-<sha1>; reproduce it with
#   build-fuzz/fuzz/<target> build-fuzz/runs/<target>/artifacts/<file>
# Exit status: 0 with no finding, 1 with one or more, 2 when the build fails.
set -uo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift $(( $# > 0 ? 1 : 0 ))
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(gltf_loader_fuzz camera_json_fuzz)

bash tools/install-deps.sh --fuzz || { echo "fuzz: could not install clang-14 (tools/install-deps.sh --fuzz)"; exit 2; }
{ cmake --preset fuzz >/dev/null && cmake --build --preset fuzz; } || { echo "fuzz: build failed"; exit 2; }

runs=build-fuzz/runs
findings_total=0
summary=()
for target in "${targets[@]}"; do
  case $target in
    gltf_loader_fuzz) kind=gltf ;;
    camera_json_fuzz) kind=camera ;;
    *) echo "fuzz: unknown target $target"; exit 2 ;;
  esac
  work=$runs/$target
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/artifacts"
  cp fuzz/corpus/$kind/* "$work/corpus/"
  seeds=$(ls "$work/corpus" | wc -l)
  echo "fuzz: $target for ${seconds}s from $seeds seeds (log: $work/log)"
  # detect_leaks stays on: the fuzz targets load no GL driver.
  ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_stack_use_after_return=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    build-fuzz/fuzz/$target "$work/corpus" -dict=fuzz/$kind.dict -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -artifact_prefix="$work/artifacts/" -print_final_stats=1 >"$work/log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | tail -1)
  # libFuzzer's own rate (the last status line); the final stats' average as a fallback.
  rate=$(grep -o 'exec/s: [0-9]*' "$work/log" | tail -1 | cut -d' ' -f2)
  [ -n "$execs" ] && [ "$seconds" -gt 0 ] && rate=${rate:-$((execs / seconds))}
  corpus=$(ls "$work/corpus" | wc -l)
  findings=$(ls "$work/artifacts" | wc -l)
  if [ "$rc" -ne 0 ] && [ "$findings" -eq 0 ]; then findings=1; fi  # died without writing its input
  findings_total=$((findings_total + findings))
  line="$target: ${execs:-?} executions, ${rate:-?} exec/s, corpus $seeds -> $corpus files, $findings findings"
  summary+=("$line")
  echo "fuzz: $line"
  if [ "$findings" -gt 0 ]; then
    grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|runtime error:|terminate called|==[0-9]+==' "$work/log" | sed 's/^/fuzz:   /'
    ls "$work/artifacts" | sed "s|^|fuzz:   $work/artifacts/|"
  fi
done

echo "fuzz: summary (${seconds}s per target)"
printf '  %s\n' "${summary[@]}"
[ "$findings_total" -eq 0 ] || exit 1
