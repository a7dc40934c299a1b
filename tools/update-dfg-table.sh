#!/bin/bash
# Regenerates src/scene/DfgTableValues.inc, the baked split-sum DFG table (scene/Brdf.h), whole,
# after a change to the BRDF or to the table's size (kDfgTableSize in src/scene/Brdf.h with
# kDfgSize in shaders/common/brdf.glsl; the generator builds without the values it replaces).
# Usage: tools/update-dfg-table.sh [build-dir]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target lenslab_make_dfg_table
"$build/tests/lenslab_make_dfg_table" > src/scene/DfgTableValues.inc.new
mv src/scene/DfgTableValues.inc.new src/scene/DfgTableValues.inc
echo "wrote src/scene/DfgTableValues.inc; rebuild and run: ctest --test-dir $build -R unit"
