#!/usr/bin/env bash
# Regenerates tests/golden/*.png from the current renderer. Review every changed image (git diff
# shows them as binary; open them) before committing: a golden is a claim that the image is right.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$top/build"}
cmake --build "$build" --target lenslab_gl_tests
LENSLAB_UPDATE_GOLDENS=1 "$build/tests/lenslab_gl_tests" --gtest_filter='*Golden*'
git -C "$top" status --short tests/golden
