#!/usr/bin/env bash
# lenslab installed, moved, and used with its source and build trees out of reach:
#   1. `cmake --install BUILD --prefix STAGE` (the Dockerfile's install step), then STAGE moved
#      elsewhere: the prefix must be relocatable;
#   2. from an unrelated folder, with the trees hidden, the moved `bin/lenslab render` (its bundled
#      scene, pinhole and thin lens), and examples/render-frame configured with
#      find_package(lenslab), built and run against the moved prefix;
#   3. the images equal the build tree's `lenslab render` of the same camera (PSNR bound), the
#      example's is the right size and not blank; without its assets folder the installed lenslab
#      says so in one line and LENSLAB_ASSET_DIR brings them back.
# The trees are hidden in a private mount namespace (`unshare -m`, an empty folder bind-mounted
# over each; as root, or through a user namespace). Where that is not allowed, step 2 runs under
# `strace -f -e trace=%file` and no file-path system call may name either tree. Neither possible:
# exit 77 (skipped). LENSLAB_INSTALL_TEST_MODE=strace forces the strace way.
# usage: install_test.sh SOURCE_DIR BUILD_DIR path/to/lenslab_image_check
set -u

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# ---- step 2, run as its own process: inside the namespace, or under strace ----
# install_test.sh --isolated MODE WORK PREFIX [SOURCE_DIR BUILD_DIR]
if [ "${1:-}" = --isolated ]; then
  mode=$2 work=$3 prefix=$4
  if [ "$mode" = mount ]; then
    src=$5 build=$6
    # The build tree first: it may lie inside the source tree.
    for tree in "$build" "$src"; do
      mount --bind "$work/empty" "$tree" || { echo "FAIL: cannot hide $tree"; exit 1; }
    done
    # (a build tree inside the source tree is now gone altogether)
    for tree in "$src" "$build"; do
      if [ -e "$tree" ] && [ -n "$(ls -A "$tree")" ]; then echo "FAIL: $tree is still visible"; exit 1; fi
    done
  fi
  unset LENSLAB_SHADER_DIR LENSLAB_ASSET_DIR
  cd "$work/cwd" || exit 1
  out=$work/out
  if [ ! -e "$prefix/share/lenslab/shaders" ]; then pass; else fail "shaders installed as files: they are compiled in"; fi

  # The bundled scene (found next to the executable), through a pinhole and through a thin lens.
  if "$prefix/bin/lenslab" render --width 160 --out "$out/installed.png" -q; then pass
  else fail "installed lenslab render (default scene)"; fi
  if "$prefix/bin/lenslab" render --camera "$work/f2.json" --aperture-samples 32 --width 160 --out "$out/installed-f2.png" -q
  then pass; else fail "installed lenslab render --camera f2.json"; fi

  # The library from CMake: the example, configured, built and run against the moved prefix.
  if cmake -S "$work/example" -B "$work/example-build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >"$work/example.log" 2>&1 &&
     cmake --build "$work/example-build" >>"$work/example.log" 2>&1; then pass
  else fail "examples/render-frame does not build against the installed package: $(tail -20 "$work/example.log")"; fi
  if "$work/example-build/render-frame" "$out/example.png" 160 2 >"$work/example-run.log" 2>&1; then pass
  else fail "render-frame: $(cat "$work/example-run.log")"; fi

  # No assets folder: one line naming what to set, a non-zero exit, no image; the override works.
  mv "$prefix/share/lenslab/assets" "$work/assets-elsewhere"
  "$prefix/bin/lenslab" render --width 160 --out "$out/no-assets.png" >/dev/null 2>"$work/no-assets.err"
  rc=$?
  if [ "$rc" -ne 0 ] && [ "$(wc -l <"$work/no-assets.err")" -eq 1 ] && grep -q LENSLAB_ASSET_DIR "$work/no-assets.err" &&
     [ ! -e "$out/no-assets.png" ]; then pass
  else fail "without share/lenslab/assets: exit $rc, stderr: $(cat "$work/no-assets.err")"; fi
  if LENSLAB_ASSET_DIR=$work/assets-elsewhere "$prefix/bin/lenslab" render --width 160 --out "$out/env-assets.png" -q; then pass
  else fail "LENSLAB_ASSET_DIR=... lenslab render"; fi
  mv "$work/assets-elsewhere" "$prefix/share/lenslab/assets"

  echo "isolated ($mode): $passed passed, $failed failed"
  exit $((failed > 0))
fi

# ---- the test ----
src=$(realpath "$1")
build=$(realpath "$2")
image_check=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/lenslab-install-test.XXXXXX")
work=$(realpath "$work")
trap '[ -n "${LENSLAB_KEEP_TEST_FILES:-}" ] || rm -rf "$work"' EXIT  # set it to look at what the test left
for tree in "$src" "$build"; do
  case "$work/" in "$tree"/*) echo "FAIL: the scratch folder $work lies inside $tree, which the test hides"; exit 1 ;; esac
done

# How the trees are hidden: a mount namespace (as root, or as a mapped root in a user namespace),
# else strace, else skip.
mode=${LENSLAB_INSTALL_TEST_MODE:-}
unshare_cmd=()
if [ -z "$mode" ]; then
  for candidate in "unshare -m --propagation private" "unshare -r -m --propagation private"; do
    if $candidate mount --bind "$work" "$work" 2>/dev/null; then mode=mount; read -r -a unshare_cmd <<<"$candidate"; break; fi
  done
fi
if [ -z "$mode" ] && strace -f -qq -e trace=%file -o /dev/null true 2>/dev/null; then mode=strace; fi
if [ -z "$mode" ]; then
  echo "SKIPPED: neither a private mount namespace (unshare -m) nor strace is available to hide the source and build trees"
  exit 77
fi
echo "install test: hiding the source and build trees by $([ "$mode" = mount ] && echo "a private mount namespace (${unshare_cmd[*]})" || echo "strace (no file-path system call may name them)")"

# 1. Install (as the Dockerfile does) and move the prefix.
if cmake --install "$build" --prefix "$work/stage" >"$work/install.log" 2>&1; then pass
else fail "cmake --install: $(tail -5 "$work/install.log")"; exit 1; fi
mkdir -p "$work/moved/opt"
mv "$work/stage" "$work/moved/opt/lenslab"
prefix=$work/moved/opt/lenslab
for f in bin/lenslab share/lenslab/assets/rows/rows.gltf include/lenslab/camera/Camera.h include/lenslab/glad/gl.h \
         lib/cmake/lenslab/lenslabConfig.cmake lib/cmake/lenslab/lenslabConfigVersion.cmake lib/cmake/lenslab/lenslabTargets.cmake; do
  if [ -e "$prefix/$f" ]; then pass; else fail "not installed: $f"; fi
done
# No installed text file (headers, package config) names the trees. The binaries do hold them: a
# build-tree executable reads the source tree's shaders (core/DataPaths.h); step 2 shows that an
# installed one never does.
if named=$(grep -rlI -e "$src" -e "$build" "$prefix"); then fail "installed files name the source or build tree: $named"; else pass; fi

# What step 2 needs, outside the trees: the example's sources, a thin-lens camera, empty folders.
mkdir -p "$work/cwd" "$work/out" "$work/empty"
cp -r "$src/examples/render-frame" "$work/example"
cp "$0" "$work/install_test.sh"
# The rows camera (assets/rows/camera.json) at f/2: what examples/render-frame renders.
cat >"$work/f2.json" <<'EOF'
{"eye": [0.0, 1.0, 3.0], "target": [0.0, 0.55, -2.0], "up": [0, 1, 0], "focal_length_mm": 35,
 "sensor_mm": [36, 24], "focus_distance": 4.0, "near": 0.05, "far": "infinity", "f_number": 2.0}
EOF
# The references, from the build tree.
"$build/lenslab" render --width 160 --out "$work/ref.png" -q || fail "build/lenslab render"
"$build/lenslab" render --camera "$work/f2.json" --aperture-samples 32 --width 160 --out "$work/ref-f2.png" -q ||
  fail "build/lenslab render --camera f2.json"

# 2. The installed lenslab and the example, the trees out of reach.
if [ "$mode" = mount ]; then
  "${unshare_cmd[@]}" bash "$work/install_test.sh" --isolated mount "$work" "$prefix" "$src" "$build"
  rc=$?
else
  # (OLDPWD unset: bash checks at start-up that the folder it names exists)
  (cd "$work/cwd" && unset OLDPWD && strace -f -qq -e trace=%file -o "$work/trace" bash "$work/install_test.sh" --isolated strace "$work" "$prefix")
  rc=$?
  opened=$(grep -F -e "\"$src/" -e "\"$src\"" -e "\"$build/" -e "\"$build\"" "$work/trace" | head -5)
  if [ -z "$opened" ]; then pass
  else fail "the installed lenslab or the example reached into the trees: $opened"; fi
fi
if [ "$rc" -eq 0 ]; then pass; else fail "step 2 (isolated) failed"; fi

# 3. The images. The same code on the same machine: equal, or all but (≥ 50 dB; f/8 instead of
# f/2 gives 40 dB, a missing texture far less).
check_same() {
  if [ ! -s "$2" ]; then fail "$3: no image"; return; fi
  if result=$("$image_check" psnr "$1" "$2" 50); then pass; else fail "$3 differs from the build tree's: $result"; fi
}
check_same "$work/ref.png" "$work/out/installed.png" "installed lenslab render"
check_same "$work/ref-f2.png" "$work/out/installed-f2.png" "installed lenslab render at f/2"
check_same "$work/ref.png" "$work/out/env-assets.png" "installed lenslab with LENSLAB_ASSET_DIR"
check_same "$work/ref-f2.png" "$work/out/example.png" "examples/render-frame"
# The example's image: 160 wide, 3:2 (160 × 107), and not blank (the rows have texture and edges).
if [ -s "$work/out/example.png" ]; then
  if iinfo "$work/out/example.png" | grep -q "160 x  *107"; then pass; else fail "example.png size: $(iinfo "$work/out/example.png")"; fi
  if result=$("$image_check" busy "$work/out/example.png" 0 0 160 107 0.05); then pass; else fail "example.png is blank: $result"; fi
fi

echo "install test ($mode): $passed passed, $failed failed"
[ "$failed" -eq 0 ]
