# shellcheck shell=bash
# Sourced by the tests of the plotting scripts (plot_run_test.sh, plot_batch_test.sh,
# plot_block_belt_test.sh), after `set -euo pipefail`, with their arguments POUND_BINARY REPO_ROOT.
# Checks the arguments and defines: fail, $python (a python3 that imports matplotlib), $tmp (a
# scratch folder removed on exit, also holding MPLCONFIGDIR), is_png, and for a test that sets
# $script (the plotting script) check_folder and expect_input_error.
# shellcheck source-path=SCRIPTDIR source=tool_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/tool_test_common.sh"  # the arguments, fail, $tmp

# Debian's python3-matplotlib is seen by /usr/bin/python3, not necessarily by the python3 on PATH
# (pyenv, a venv): take the first of the two that can import it.
python=""
for candidate in /usr/bin/python3 python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" >/dev/null 2>&1; then
    python=$(command -v "$candidate")
    break
  fi
done
[ -n "$python" ] || fail "matplotlib is not importable by /usr/bin/python3 nor by python3 on PATH; \
install it with tools/install_dependencies.sh (Debian package python3-matplotlib)"
echo "using $python"
export MPLCONFIGDIR="$tmp/matplotlib"

is_png() {  # a PNG signature and more than a blank canvas
  local file=$1
  [ -f "$file" ] || fail "$file was not written"
  [ "$(head -c 8 "$file" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ||
    fail "$file is not a PNG"
  [ "$(stat -c %s "$file")" -gt 10000 ] || fail "$file is only $(stat -c %s "$file") bytes"
}

check_folder() {  # folder, expected PNGs...: each written and printed, one line per PNG, no leftovers
  local folder=$1
  shift
  local png
  for png in "$@"; do
    is_png "$folder/$png"
    grep -qx "$folder/$png" "$tmp/stdout" || fail "$(basename "${script:?}") did not print $folder/$png"
  done
  local written
  written=$(find "$folder" -maxdepth 1 -name '*.png' | wc -l)
  [ "$(wc -l <"$tmp/stdout")" -eq "$written" ] ||
    fail "expected one line per PNG written ($written), got: $(cat "$tmp/stdout")"
  ! ls -A "$folder" | grep -q '\.tmp\.' || fail "temporary files left in $folder"
}

# Bad input: exit 2, a message naming the folder or file, never a traceback, no PNG written.
expect_input_error() {  # folder, text the message must contain
  local status=0
  "$python" "$script" "$1" >/dev/null 2>"$tmp/stderr" || status=$?
  [ "$status" -eq 2 ] || fail "expected exit 2 for $1, got $status: $(cat "$tmp/stderr")"
  grep -qF "$2" "$tmp/stderr" || fail "message for $1 does not name $2: $(cat "$tmp/stderr")"
  ! grep -q Traceback "$tmp/stderr" || fail "traceback for $1: $(cat "$tmp/stderr")"
  ! find "$1" -maxdepth 1 -name '*.png' 2>/dev/null | grep -q . || fail "PNGs written into $1"
}
