#!/usr/bin/env bash
# The unit and command-line tests under AddressSanitizer + UndefinedBehaviorSanitizer (gcc).
# usage: tools/sanitize.sh [--gl]       --gl: also the GL tests (Mesa llvmpipe under ASan; slow)
# Configures and builds the asan preset (CMakePresets.json: build-asan, LENSLAB_SANITIZE=ON,
# -O1 -g with asserts on) and runs the ctest entries labelled unit and cli (and gl). Any ASan or
# UBSan report aborts the process, so it fails its test.
# Sanitizer options: the defaults are compiled into every executable of the build
# (tools/sanitizers/sanitizer_defaults.cpp: ASan, UBSan and the LeakSanitizer suppressions for
# the Mesa GL driver), so that `ctest --test-dir build-asan` alone runs the same way; variables
# ASAN_OPTIONS, UBSAN_OPTIONS and LSAN_OPTIONS in the environment add to or override them.
set -euo pipefail
cd "$(dirname "$0")/.."

labels='^(unit|cli)$'
targets=(lenslab_unit_tests lenslab lenslab_image_check)
if [ "${1:-}" = "--gl" ]; then
  labels='^(unit|cli|gl)$'
  targets+=(lenslab_gl_tests)
fi

start=$(date +%s)
cmake --preset asan >/dev/null
cmake --build build-asan --target "${targets[@]}"
built=$(date +%s)
# Two at a time: 683 s against 1206 s serial on two cores (the tests keep to their own folders).
ctest --test-dir build-asan -L "$labels" -j2 --output-on-failure
echo "sanitize: build $((built - start)) s, tests $(($(date +%s) - built)) s"
