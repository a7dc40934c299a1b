#!/usr/bin/env bash
# Outputs whole or not at all on a real full disk: a 16 KiB tmpfs (ENOSPC), a full one, and a
# read-only bind mount (EROFS, which stops root too). Needs mount(2): where it is not allowed
# (not root, a container without CAP_SYS_ADMIN) it exits 77, which ctest shows as skipped; the
# checks that need no mount are in fault_test.sh and always run.
# usage: tmpfs_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
mounts=()
cleanup() {
  for m in "${mounts[@]}"; do umount "$m" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
. "$(dirname "$0")/fault_lib.sh"

small=$work/small
mkdir -p "$small"
if ! reason=$(mount -t tmpfs -o size=16k tmpfs "$small" 2>&1); then
  reason=$(echo "${reason:-mount failed}" | head -1)
  echo "SKIPPED: cannot mount tmpfs ($reason); fault_test.sh covers what needs no mount"
  exit 77
fi
mounts+=("$small")

# A 960-pixel render does not fit in 16 KiB: it used to give exit 0, "wrote" and a 16 KiB PNG.
expect_fault "PNG on a 16 KiB tmpfs" "$small/x.png: cannot write it: No space left on device" "$small" - -- render --width 960 --out "$small/x.png"
expect_fault "EXR on a 16 KiB tmpfs" "$small/x.exr: cannot write it: No space left on device" "$small" - -- render --width 960 --out "$small/x.exr"
expect_fault "sweep on a 16 KiB tmpfs" "No space left on device" "$small" - \
  -- sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera-dof.json" --out "$small/sweep" \
  --width 24 --reference-spp 4 --max-views 2 --max-spp 1
# Full to the last byte: refused before rendering (the probe cannot write), stats or image.
head -c 1M /dev/zero >"$small/filler" 2>/dev/null
expect_fault "--out on a full tmpfs" "--out $small/x.png: cannot write in the folder $small: No space left on device" "$small" - \
  -- render --width 960 --out "$small/x.png"
expect_fault "--stats on a full tmpfs" "--stats $small/s.json: cannot write in the folder $small: No space left on device" "$work" - \
  -- render --width 16 --out "$work/x.png" --stats "$small/s.json"

# --stats into a read-only folder: refused before rendering, so the image is not written either.
mkdir -p "$work/ro-source" "$work/ro"
if reason=$(mount --bind -o ro "$work/ro-source" "$work/ro" 2>&1) || reason=$(mount -o remount,ro,bind "$work/ro" 2>&1); then
  mounts=("$work/ro" "${mounts[@]}")
  expect_fault "--stats into a read-only mount" "--stats $work/ro/s.json: cannot write in the folder $work/ro: Read-only file system" "$work" - \
    -- render --width 16 --out "$work/x.png" --stats "$work/ro/s.json"
else
  fail "read-only bind mount: $reason"
fi

echo "tmpfs: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
