#!/usr/bin/env bash
# tools/plot_pushover.py on a real pushover: the figure exists and is a PNG; bad input exits 2.
# usage: plot_pushover_test.sh POUND_BINARY REPO_ROOT
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=plot_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/plot_test_common.sh"  # fail, $python, $tmp, check_folder...
pound=$1
root=$2
script="$root/tools/plot_pushover.py"

# 1. The hinged bridge pushed at pier 1's top past its first yield.
push="$tmp/push"
"$pound" pushover "$root/models/three_span_bridge_takeda.json" --node bridge.p1.top --to 0.02 \
  --increments 20 --out "$push" >/dev/null || fail "pound pushover failed"
status=0
"$python" "$script" "$push" --dpi 60 >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "plot_pushover.py exited $status on a good folder: $(cat "$tmp/stderr")"
check_folder "$push" pushover.png

# 2. Bad input: exit 2, a message naming the file, no traceback, no PNG.
expect_input_error "$tmp/does_not_exist" "$tmp/does_not_exist"
mkdir "$tmp/no_summary"
cp "$push/pushover.csv" "$tmp/no_summary/"
expect_input_error "$tmp/no_summary" "pushover.json"
mkdir "$tmp/bad_cell"
cp "$push/pushover.json" "$tmp/bad_cell/"
{ head -n 2 "$push/pushover.csv"; echo "0.1,nan?,3"; } >"$tmp/bad_cell/pushover.csv"
expect_input_error "$tmp/bad_cell" "pushover.csv"
echo "plot_pushover: ok"
