# Shared by fault_test.sh and tmpfs_test.sh (sourced; needs $lenslab and $work set): run lenslab
# where a write must fail or a path must be refused, and check that nothing new is left.
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"

# Every name under a folder, dot files (temporaries, probes) and folders included.
listing() { (cd "$1" && find . | LC_ALL=C sort); }

# run_lenslab LIMIT_KB ARGS...: lenslab, with each file it writes limited to LIMIT_KB KiB ("-": no
# limit). A write past the limit then fails with EFBIG ("File too large"), as one on a full disk
# fails with ENOSPC. SIGXFSZ is ignored first, so that the write fails instead of the signal
# killing the process; an ignored signal stays ignored through exec.
run_lenslab() {
  local limit=$1
  shift
  (
    trap '' XFSZ
    if [ "$limit" != - ]; then ulimit -f "$limit"; fi
    exec $as_user "$lenslab" "$@"
  ) >"$work/stdout" 2>"$work/stderr"
}

# expect_fault NAME FRAGMENT WATCHED LIMIT_KB -- ARGS...: a non-zero exit, one line on stderr
# holding FRAGMENT (besides progress, warning and the sweep's lines), and the folder WATCHED exactly as it was
# (no target, no temporary file, no folder made by the run).
expect_fault() {
  local name=$1 fragment=$2 watched=$3 limit=$4
  shift 5
  local before
  before=$(listing "$watched")
  run_lenslab "$limit" "$@"
  local rc=$?
  local lines
  lines=$(grep -vcE "^lenslab: sweep: |$progress_line" "$work/stderr")
  if [ "$rc" -eq 0 ]; then fail "$name: exit 0: $(cat "$work/stderr")"; return; fi
  if [ "$lines" -ne 1 ]; then fail "$name: $lines stderr lines: $(cat "$work/stderr")"; return; fi
  if ! grep -qF -- "$fragment" "$work/stderr"; then fail "$name: stderr lacks '$fragment': $(cat "$work/stderr")"; return; fi
  local after
  after=$(listing "$watched")
  if [ "$before" != "$after" ]; then fail "$name: left $(diff <(echo "$before") <(echo "$after") | grep '^>' | tr '\n' ' ')"; return; fi
  pass
}

as_user=""  # a command prefix that runs lenslab as another user (fault_test.sh: nobody)
# The run's stdout and stderr live in $work from the start, so that a folder listing of $work
# before a run equals the one after it.
: >"$work/stdout"
: >"$work/stderr"
