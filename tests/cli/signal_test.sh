#!/usr/bin/env bash
# Interrupted runs leave nothing unfinished: Ctrl-C (SIGINT) and SIGTERM during a long write, a
# sweep and a capture remove the run's hidden temporary files and the empty folders it made, and
# exit 128 + the signal with one line saying so; a file size limit (SIGXFSZ, `ulimit -f`) is one
# error line naming the file, not a silent death. Also: a target name of NAME_MAX (255) bytes is
# written (the temporary name beside it is short).
# usage: signal_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
. "$(dirname "$0")/fault_lib.sh"
# Background jobs of a script ignore SIGINT unless job control is on (a Ctrl-C at a terminal
# reaches a foreground process whose SIGINT is not ignored; this is the same).
set -m

# interrupt NAME SIGNAL WATCHED WAIT_FOR -- ARGS...: starts lenslab ARGS, waits until the path
# WAIT_FOR exists (a glob: the run has started writing), sends SIGNAL, and checks the exit code
# (128 + the signal's number), the one line, and that WATCHED lists as before.
interrupt() {
  local name=$1 sig=$2 watched=$3 wait_for=$4
  shift 5
  local before
  before=$(listing "$watched")
  "$lenslab" "$@" >"$work/stdout" 2>"$work/stderr" &
  local pid=$! started=0
  for _ in $(seq 1 600); do
    # shellcheck disable=SC2086  # the glob is meant to expand
    if compgen -G "$wait_for" >/dev/null; then started=1; break; fi
    if ! kill -0 "$pid" 2>/dev/null; then break; fi
    sleep 0.05
  done
  if [ "$started" -ne 1 ]; then
    kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    fail "$name: $wait_for never appeared (too fast a run to interrupt?): $(cat "$work/stderr")"
    return
  fi
  kill "-$sig" "$pid"
  wait "$pid"
  local rc=$? expected
  expected=$((128 + $(kill -l "$sig")))
  if [ "$rc" -ne "$expected" ]; then fail "$name: exit $rc, not $expected: $(cat "$work/stderr")"; return; fi
  if ! grep -qE "^lenslab: interrupted \\(SIG$sig\\)" "$work/stderr"; then fail "$name: no 'interrupted (SIG$sig)' line: $(cat "$work/stderr")"; return; fi
  local lines
  lines=$(grep -vcE "^lenslab: sweep: |$progress_line|^\$" "$work/stderr")
  if [ "$lines" -ne 1 ]; then fail "$name: $lines stderr lines: $(cat "$work/stderr")"; return; fi
  local after
  after=$(listing "$watched")
  if [ "$before" != "$after" ]; then fail "$name: left $(diff <(echo "$before") <(echo "$after") | grep '^>' | tr '\n' ' ')"; return; fi
  pass
}

out=$work/out
mkdir -p "$out"
# A tiled render whose image goes to its temporary file strip by strip for seconds: the hidden
# file (.lenslab-PID-….tmp.png) exists from the first strip on. Not any hidden file: the
# writability probe (.lenslab-probe-…) lives for an instant before it, and a signal then finds no
# file to remove (seen with two tests at a time).
big=(render --width 4000 --tile-size 256 --aperture-samples 1 -q)
interrupt "SIGINT during a streamed PNG" INT "$out" "$out/.lenslab-*.tmp*" -- "${big[@]}" --out "$out/big.png"
interrupt "SIGTERM during a streamed PNG" TERM "$out" "$out/.lenslab-*.tmp*" -- "${big[@]}" --out "$out/big.png"
if grep -qF "removed 1 unfinished file" "$work/stderr"; then pass; else fail "SIGTERM: the line does not count the file removed: $(cat "$work/stderr")"; fi
interrupt "SIGHUP during a streamed EXR" HUP "$out" "$out/.lenslab-*.tmp*" -- "${big[@]}" --out "$out/big.exr"

# A sweep: the folders it made (out/sweep and out/sweep/images, made before the reference) go.
interrupt "SIGTERM during a sweep" TERM "$out" "$out/sweep/images" -- sweep --out "$out/sweep" --width 96 --reference-spp 4096 -q

# A capture into a new folder, interrupted during its first frame: the folder goes too.
capture=(capture --path "$src/assets/rows/rack-focus.json" --width 1200 --aperture-samples 64 -q)
interrupt "SIGINT during a capture's first frame" INT "$out" "$out/frames" -- "${capture[@]}" --out "$out/frames/frame_%04d.png"

# Interrupted after some frames: those stay, each with its manifest line; nothing else does.
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --width 320 --aperture-samples 16 -q \
  --out "$out/seq/frame_%04d.png" >"$work/stdout" 2>"$work/stderr" &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$out/seq/frame_0001.png" ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -TERM "$pid"
wait "$pid"
rc=$?
hidden=$(find "$out/seq" -name '.*' | wc -l)
images=$(find "$out/seq" -name 'frame_*.png' | wc -l)
cameras=$(find "$out/seq" -name 'frame_*.camera.json' | wc -l)
lines=$(wc -l <"$out/seq/manifest.jsonl")
if [ "$rc" -eq 143 ] && [ "$hidden" -eq 0 ] && [ "$images" -ge 1 ] && [ "$images" -eq "$lines" ] && [ "$cameras" -eq "$images" ]; then pass
else fail "capture interrupted after some frames: exit $rc, $hidden hidden files, $images images, $cameras cameras, $lines lines: $(cat "$work/stderr")"; fi

# ---- a file size limit (ulimit -f): SIGXFSZ used to kill the process silently ----
before=$(listing "$out")
( ulimit -f 16; exec "$lenslab" render --width 960 --out "$out/limited.png" -q ) >"$work/stdout" 2>"$work/stderr"
rc=$?
if [ "$rc" -eq 1 ] && grep -qF "$out/limited.png: cannot write it: File too large" "$work/stderr" && [ "$before" = "$(listing "$out")" ]; then pass
else fail "ulimit -f 16: exit $rc, left $(diff <(echo "$before") <(listing "$out") | grep '^>' | tr '\n' ' '): $(cat "$work/stderr")"; fi

# ---- names up to NAME_MAX ----
name255=$(printf 'n%.0s' $(seq 1 251)).png
if "$lenslab" render --width 16 -q --out "$out/$name255" 2>"$work/stderr" && [ -f "$out/$name255" ]; then pass
else fail "a 255-byte output name: $(cat "$work/stderr")"; fi
rm -f "$out/$name255"
# One byte more is refused before rendering, naming the limit.
if one_line_error "a 256-byte output name" "bytes; the file system in $out allows 255" -- render --width 16 -q --out "$out/n$name255" \
  && [ ! -e "$out/n$name255" ]; then pass; fi
# capture's camera file (frame_N.camera.json) is longer than its image's name: refused up front.
long=$(printf 'c%.0s' $(seq 1 240))_%04d.png
if one_line_error "a capture whose camera file name is too long" "camera.json: the file name is" \
  -- capture --path "$src/assets/rows/rack-focus.json" --width 16 --frames 0 -q --out "$out/long/$long" \
  && [ ! -e "$out/long" ]; then pass; fi

echo "signals: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
