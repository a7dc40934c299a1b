# Shared by the cli tests (sourced; needs $lenslab and $work set): counters, and the check that a
# refused command says so the way every lenslab error does.
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

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
