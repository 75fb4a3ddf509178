# shellcheck shell=bash
# Sourced by the tests of the Python tools (directly, or through plot_test_common.sh), after
# `set -euo pipefail`, with their arguments POUND_BINARY REPO_ROOT. Checks the arguments and
# defines fail and $tmp, a scratch folder removed on exit.
if [ $# -ne 2 ]; then
  echo "usage: $0 POUND_BINARY REPO_ROOT" >&2
  exit 1
fi

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
