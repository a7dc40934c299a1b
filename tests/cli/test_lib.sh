# Shared by the cli tests (sourced; its functions need $lenslab and $work set, which
# cli_test_setup does): counters, the check that a refused command says so the way every lenslab
# error does, and small checks on files.
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
python=/usr/bin/python3

# cli_test_setup "$@": a cli test's arguments (path/to/lenslab source-dir) as $lenslab and $src,
# unset variables as errors, and a fresh folder $work, removed on exit (made writable first: some
# tests take the write permission away from folders in it). A test with more to undo sets its own
# EXIT trap after this.
cli_test_setup() {
  set -u
  lenslab=$1
  src=$2
  work=$(mktemp -d)
  trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
}

# check COMMAND ARGS...: counts a pass when the command succeeds, else a failure naming it.
check() { if "$@"; then pass; else fail "$*"; fi; }
# holds FILE EXPRESSION: true when the Python expression over the JSON file (j) is true, e.g.
# holds s.json 'close(j["lens"]["f_number"], 2)' (close A B [relative tolerance]: lists or numbers).
holds() {
  $python -c "import json,sys,math; j=json.load(open(sys.argv[1])); close=lambda a,b,t=1e-9: all(abs(x-y)<=t*max(1,abs(y)) for x,y in zip(a if isinstance(a,list) else [a], b if isinstance(b,list) else [b])); sys.exit(0 if ($2) else 1)" "$1"
}
# Identical pixels in every channel (Z too; idiff counts +inf = +inf as equal).
same_pixels() { idiff -fail 0 -warn 0 "$1" "$2" >/dev/null 2>&1; }

# Lines that are not the error: progress ("lenslab: render: 37/98 samples, 12.3 s, ...", which a
# slow machine may write before an error) and warnings about other input (a small --width whose
# rounded height makes pixels not quite square).
progress_line='^lenslab: ([a-z]+: [0-9]+/[0-9]+ |warning: )'

# one_line_error NAME EXPECTED_FRAGMENT -- ARGS...: runs lenslab ARGS; true when it exits non-zero
# with one stderr line (besides progress and warning lines) holding the fragment, else counts a
# failure (naming NAME) and is false. The caller then checks that nothing was written, and counts
# the pass.
one_line_error() {
  local name=$1 fragment=$2
  shift 3
  "$lenslab" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  local lines
  lines=$(grep -vcE "$progress_line" "$work/stderr")
  if [ "$rc" -eq 0 ]; then fail "$name: exit 0"; return 1; fi
  if [ "$lines" -ne 1 ]; then fail "$name: $lines stderr lines: $(cat "$work/stderr")"; return 1; fi
  if ! grep -qF -- "$fragment" "$work/stderr"; then fail "$name: stderr lacks '$fragment': $(cat "$work/stderr")"; return 1; fi
  return 0
}

# expect_refusal NAME EXPECTED_FRAGMENT -- ARGS...: one_line_error, and nothing written to
# $work/$refused_outputs (a glob; out.* unless the test sets it) or its hidden temporary files.
refused_outputs='out.*'
expect_refusal() {
  # shellcheck disable=SC2086  # the glob is meant to expand
  rm -rf "$work"/$refused_outputs "$work"/.$refused_outputs
  one_line_error "$@" || return
  # shellcheck disable=SC2086
  if ls "$work"/$refused_outputs "$work"/.$refused_outputs >/dev/null 2>&1; then fail "$1: left an output file"; return; fi
  pass
}
