# shellcheck shell=bash
# Sourced by the tests of the plotting scripts (plot_run_test.sh, plot_batch_test.sh,
# plot_block_belt_test.sh), after `set -euo pipefail`, with their arguments POUND_BINARY REPO_ROOT.
# Checks the arguments and defines: fail, $python (a python3 that imports matplotlib), $tmp (a
# scratch folder removed on exit, also holding MPLCONFIGDIR) and is_png.
if [ $# -ne 2 ]; then
  echo "usage: $0 POUND_BINARY REPO_ROOT" >&2
  exit 1
fi

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

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

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export MPLCONFIGDIR="$tmp/matplotlib"

is_png() {  # a PNG signature and more than a blank canvas
  local file=$1
  [ -f "$file" ] || fail "$file was not written"
  [ "$(head -c 8 "$file" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ||
    fail "$file is not a PNG"
  [ "$(stat -c %s "$file")" -gt 10000 ] || fail "$file is only $(stat -c %s "$file") bytes"
}
