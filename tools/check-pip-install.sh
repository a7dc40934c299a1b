#!/usr/bin/env bash
# `pip install .` as a user runs it (docs/python.md), checked: a fresh virtual environment of
# Debian's python3, the package built from SOURCE by scikit-build-core (the C++ dependencies are
# Debian's, from tools/install-deps.sh; scikit-build-core, pybind11 and NumPy come from the Python
# package registry), then `import lenslab` from an unrelated folder: the bundled scene found in the
# installed package (not the source tree), a frame rendered and ray cast, and the frame equal, bit
# for bit, to the command line's EXR when a build tree's lenslab is given.
# Run by .ci/run after the test suite (about 10 min on 2 cores: the libraries are compiled again).
# Exit 77 (not run) when the registry cannot be reached.
# usage: tools/check-pip-install.sh [SOURCE_DIR [path/to/build/lenslab]]
set -euo pipefail
src=$(cd "${1:-$(dirname "$0")/..}" && pwd)
cli=${2:+$(realpath "$2")}
work=$(mktemp -d /tmp/lenslab-pip.XXXXXX)
trap 'rm -rf "$work"' EXIT

python=/usr/bin/python3
"$python" -m venv "$work/venv"
pip=("$work/venv/bin/pip" --disable-pip-version-check --quiet)
if ! "${pip[@]}" download --no-deps --dest "$work/probe" scikit-build-core pybind11 >/dev/null 2>&1; then
  echo "check-pip-install: not run: the Python package registry cannot be reached (pip needs scikit-build-core, pybind11, numpy)"
  exit 77
fi

start=$(date +%s)
echo "check-pip-install: pip install $src (a fresh build of the module: several minutes)"
CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2} \
  "${pip[@]}" install "$src" --config-settings=build-dir="$work/build"
echo "check-pip-install: installed in $(( $(date +%s) - start )) s"

mkdir "$work/cwd"
cd "$work/cwd"
if [ -n "$cli" ]; then
  "$cli" render --camera "$src/assets/rows/camera-dof.json" --width 96 --out "$work/cli.exr" --quiet
fi
env -u LENSLAB_ASSET_DIR -u LENSLAB_SHADER_DIR -u PYTHONPATH CLI_EXR="${cli:+$work/cli.exr}" \
  "$work/venv/bin/python" - <<'PY'
import os, sys
import numpy as np
import lenslab

assets = lenslab.asset_directory()
assert assets.startswith(sys.prefix), f"the bundled scenes came from {assets}, not the installed package"
scene = lenslab.load()
camera = lenslab.Camera.from_file(os.path.join(assets, "rows", "camera-dof.json"))
renderer = lenslab.Renderer(width=96)
frame = renderer.render(scene, camera, aovs=("depth",))
assert frame.rgba.shape == (64, 96, 4) and np.isfinite(frame.rgba).all() and frame.rgb.mean() > 0.01, frame
traced = renderer.raycast(scene, camera, spp=4)
assert np.abs(traced.rgb.mean() - frame.rgb.mean()) < 0.05, (traced.rgb.mean(), frame.rgb.mean())
if os.environ["CLI_EXR"]:
    cli = lenslab.read_image(os.environ["CLI_EXR"])
    assert np.array_equal(cli, frame.rgba), f"differs from the command line's EXR by up to {np.abs(cli - frame.rgba).max()}"
    print("check-pip-install: the installed package's frame equals the command line's EXR bit for bit")
print(f"check-pip-install: passed ({renderer.gl_renderer}; scenes from {assets})")
PY
