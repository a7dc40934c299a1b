#!/usr/bin/env bash
# Installs the Debian 12 packages lenslab builds, tests and runs with.
# Quick when everything is already present (dpkg is asked first; apt only runs for what is missing).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev
  libopenimageio-dev openimageio-tools libtinygltf-dev nlohmann-json3-dev libstb-dev
  libgtest-dev libbenchmark-dev libimgui-dev libcli11-dev libembree-dev libtbb-dev libeigen3-dev
  xvfb xauth fonts-dejavu-core python3-pil python3-yaml
  strace  # tests/install/install_test.sh, where no private mount namespace can be made
  clang-format  # tools/check-format.sh: the C++ follows .clang-format (ctest entry format)
  python3-dev pybind11-dev python3-numpy  # the Python module in the build tree and its tests (docs/python.md)
  python3-venv python3-pip                # `pip install .` into a virtual environment (tests/install/)
)
# --fuzz: also what tools/fuzz.sh needs (it asks for them itself): libFuzzer comes with clang (the
# default build stays on gcc); llvm-14 has llvm-symbolizer, for file:line in the fuzzers' reports.
# Not in the default set: about 400 MB that only fuzzing uses.
if [ "${1:-}" = "--fuzz" ]; then packages+=(clang-14 libclang-rt-14-dev llvm-14); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
