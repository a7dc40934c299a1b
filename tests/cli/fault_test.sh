#!/usr/bin/env bash
# Outputs whole or not at all, under faults that need no mount (tmpfs_test.sh has those):
#   - every output path checked before rendering: --stats into a missing folder, a file in place
#     of the folder, a folder in place of the file, a read-only folder — refused, no image written;
#   - a disk that fills up during the write (ulimit -f: EFBIG): non-zero exit, one line naming
#     the file and the reason, nothing new left — for PNG, EXR, the --stats after a written image,
#     and the sweep's reports; an older file of the same name is kept as it was.
# usage: fault_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
. "$(dirname "$0")/fault_lib.sh"
out=$work/out
mkdir -p "$out"

# ---- paths refused before rendering: the image is not written ----
touch "$out/file"
mkdir "$out/folder.json"
expect_fault "--stats into a missing folder" "--stats $out/missing/s.json: the folder $out/missing does not exist" "$out" - \
  -- render --width 16 --out "$out/x.png" --stats "$out/missing/s.json"
expect_fault "--stats under a file" "$out/file is not a folder" "$out" - -- render --width 16 --out "$out/x.png" --stats "$out/file/s.json"
expect_fault "--stats names a folder" "is a folder; give a file name" "$out" - -- render --width 16 --out "$out/x.png" --stats "$out/folder.json"
expect_fault "--out into a missing folder" "the folder $out/missing does not exist" "$out" - -- raycast --width 16 --spp 1 --out "$out/missing/x.exr"
expect_fault "sweep report under a file" "$out/file" "$out" - -- sweep --out "$out/file/sweep" --width 16
# Memory: under an address-space limit (ulimit -v) an image too big for it is refused in one line
# that says what to do, not "std::bad_alloc", and leaves nothing. (Not under AddressSanitizer,
# whose shadow memory alone is past any such limit.)
if grep -q __asan_init "$lenslab"; then
  echo "SKIP: out-of-memory check: this lenslab is built with AddressSanitizer"
else
  (
    ulimit -v 3000000
    "$lenslab" raycast -q --spp 1 --width 16384 --height 10923 --out "$out/huge.exr"
  ) >"$work/stdout" 2>"$work/stderr"
  rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$work/stderr")" -ne 1 ] || ! grep -qF "out of memory:" "$work/stderr" ||
    [ -n "$(ls -A "$out" | grep -E 'huge|^\.lenslab-' || true)" ]; then
    fail "out of memory: exit $rc: $(cat "$work/stderr")"
  else
    pass
  fi
  : >"$work/stdout"
  : >"$work/stderr"
fi

# An output that would overwrite an input of the same run, or that cannot be what it is named for.
cp "$src/assets/rows/camera.json" "$out/cam.json"
expect_fault "--stats over the --camera file" "is the --camera file this run reads" "$out" - \
  -- render --width 16 --camera "$out/cam.json" --out "$out/x.png" --stats "$out/cam.json"
expect_fault "--out empty" "--out: the file name is empty" "$out" - -- render --width 16 --out ""
expect_fault "--manifest into an image" "give a .jsonl (or .json) file name" "$out" - \
  -- capture --width 16 --path "$src/assets/rows/rack-focus.json" --frames 0:2 --out "$out/fr/f_%04d.png" --manifest "$out/fr/f_0002.png"
expect_fault "--manifest over a frame's camera file" "is frame 2's camera file" "$out" - \
  -- capture --width 16 --path "$src/assets/rows/rack-focus.json" --frames 0:2 --out "$out/fr/f_%04d.png" --manifest "$out/fr/f_0002.camera.json"
# Refused after it made its folders (the frames' and the manifest's, made first so that each file's
# place can be checked): capture removes them again, as sweep does.
expect_fault "capture refused after making its folders" "give a .jsonl (or .json) file name" "$out" - \
  -- capture --path "$src/assets/rows/rack-focus.json" --width 16 --out "$out/new/deeper/f_%04d.png" \
  --manifest "$out/new/deeper/m.png"

# A read-only folder. Root writes into a chmod 555 folder regardless, so as root the run is made
# as 'nobody' (setpriv); as any other user the chmod alone does it. (tmpfs_test.sh also tries a
# read-only bind mount, which stops root too.)
mkdir "$out/ro"
chmod 555 "$out/ro"
if [ "$(id -u)" -ne 0 ]; then
  expect_fault "--stats into a read-only folder" "cannot write in the folder $out/ro: Permission denied" "$out" - \
    -- render --width 16 --out "$out/x.png" --stats "$out/ro/s.json"
elif command -v setpriv >/dev/null && setpriv --reuid=nobody --regid=nogroup --clear-groups "$lenslab" --help >/dev/null 2>&1; then
  chmod 755 "$work"
  chmod 777 "$out"  # the image's own folder is writable: only --stats is refused
  as_user="setpriv --reuid=nobody --regid=nogroup --clear-groups"
  echo "note: the read-only folder is tried as user nobody (root writes into a chmod 555 folder)"
  expect_fault "--stats into a read-only folder (as nobody)" "cannot write in the folder $out/ro: Permission denied" "$out" - \
    -- render --width 16 --out "$out/x.png" --stats "$out/ro/s.json"
  as_user=""
else
  echo "note: running as root without setpriv and user nobody: the chmod 555 case is left to tmpfs_test.sh's read-only mount"
fi

# ---- the disk fills up during the write ----
# 16 KiB per file: a 320-pixel PNG of the rows scene is about 30 KiB, a 160-pixel EXR 41 KiB.
expect_fault "PNG past the limit" "$out/x.png: cannot write it: File too large" "$out" 16 -- render --width 320 --out "$out/x.png"
expect_fault "EXR past the limit" "$out/x.exr: cannot write it: File too large" "$out" 16 -- render --width 160 --out "$out/x.exr"
# A tiled render writes strip by strip through OpenImageIO into the run's temporary file.
expect_fault "tiled PNG past the limit" "$out/t.png: cannot write it:" "$out" 16 -- render --width 320 --tile-size 64 --out "$out/t.png"
expect_fault "tiled EXR past the limit" "$out/t.exr: cannot write it:" "$out" 16 -- render --width 160 --tile-size 64 --out "$out/t.exr"
# 1 KiB per file: the 8-pixel image (0.3 KiB) fits and is written first, the stats of a
# depth-of-field render (1.3 KiB) do not, and the image must go with them.
expect_fault "--stats past the limit" "$out/s.json: cannot write it: File too large" "$out" 1 \
  -- render --camera "$src/assets/rows/camera-dof.json" --max-samples 2 --width 8 --out "$out/x.png" --stats "$out/s.json"
# An older file of the same name stays as it was.
if run_lenslab - render --width 32 --out "$out/kept.png" -q; then
  cp "$out/kept.png" "$work/kept-before.png"
  expect_fault "overwrite past the limit" "File too large" "$out" 16 -- render --width 320 --out "$out/kept.png"
  if cmp -s "$out/kept.png" "$work/kept-before.png"; then pass; else fail "the older kept.png was changed"; fi
else
  fail "render kept.png: $(cat "$work/stderr")"
fi
# The sweep: its folders are made by the run, and the last file it writes (the plot, 21 KiB) does
# not fit, after the references, the rows' images and the tables (each under 4 KiB) did. Nothing
# of it is left, not even the folders.
expect_fault "sweep past the limit" "error_vs_time.png: cannot write it: File too large" "$out" 16 \
  -- sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera-dof.json" --out "$out/sweep/deeper" \
  --width 24 --reference-spp 4 --max-views 2 --max-spp 1

echo "fault: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
