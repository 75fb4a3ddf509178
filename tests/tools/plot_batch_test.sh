#!/usr/bin/env bash
# tools/plot_batch.py on a real batch: the figures exist and are PNGs; bad input exits 2 cleanly.
# usage: plot_batch_test.sh POUND_BINARY REPO_ROOT
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=plot_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/plot_test_common.sh"  # fail, $python, $tmp, check_folder...
pound=$1
root=$2
script="$root/tools/plot_batch.py"

# 1. A real batch: the three-span bridge under four records at four scales, two limits.
batch="$tmp/batch"
"$pound" batch "$root/sets/three_span_bridge_ida.json" --out "$batch" -q ||
  fail "pound batch sets/three_span_bridge_ida.json failed"
[ -f "$batch/batch_summary.csv" ] && [ -f "$batch/batch_stats.json" ] ||
  fail "pound batch wrote no batch_summary.csv or batch_stats.json"
status=0
"$python" "$script" "$batch" --dpi 70 >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "plot_batch.py exited $status on a good batch folder: $(cat "$tmp/stderr")"
! grep -q Traceback "$tmp/stderr" || fail "traceback on a good batch folder: $(cat "$tmp/stderr")"
expected=()
header=$(head -n 1 "$batch/batch_summary.csv")
for quantity in impacts max_pounding_force max_restrainer_force max_joint_opening \
                max_seat_movement max_drift_ratio max_ductility max_residual_drift_ratio \
                max_top_acceleration max_deck_acceleration; do
  # a figure for every quantity some case has a value of (an elastic pier has no ductility)
  "$python" -c 'import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if any(row.get(sys.argv[2]) for row in rows) else 1)' "$batch/batch_summary.csv" \
    "$quantity" && expected+=("ida_$quantity.png")
done
grep -q '"fitted"' "$batch/batch_stats.json" && expected+=(fragility.png)  # a fragility entry
[ "${#expected[@]}" -ge 2 ] || fail "expected IDA and fragility figures, header: $header"
check_folder "$batch" "${expected[@]}"

# 2. --quantity restricts the IDA figures; the python3 on PATH works too (it starts
#    /usr/bin/python3 if it has no matplotlib); failed cases and input errors are left out.
only="$tmp/only"
mkdir "$only"
cp "$batch/batch_stats.json" "$only/"
{
  cat "$batch/batch_summary.csv"
  echo 'extra/failed/x1,three_span_bridge,synthetic_firm_01,1,failed,"stopped: ""diverged"", at t = 3",0.3,0.3,3,,,,,,,,,,,,,,,,,,'
  echo 'extra/missing/x1,three_span_bridge,missing,1,input_error,"cannot read record, no such file",,,,,,,,,,,,,,,,,,,,,'
} >"$only/batch_summary.csv"
interpreter=$python
command -v python3 >/dev/null 2>&1 && interpreter=python3
status=0
"$interpreter" "$script" "$only" --dpi 60 --quantity max_joint_opening >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "$interpreter plot_batch.py --quantity exited $status: $(cat "$tmp/stderr")"
only_expected=(ida_max_joint_opening.png)
[[ " ${expected[*]} " == *" fragility.png "* ]] && only_expected+=(fragility.png)
check_folder "$only" "${only_expected[@]}"

status=0
"$python" "$script" "$only" --quantity max_joint_openin >/dev/null 2>"$tmp/stderr" || status=$?
[ "$status" -eq 1 ] || fail "expected exit 1 for an unknown --quantity, got $status: $(cat "$tmp/stderr")"
grep -q 'max_joint_opening' "$tmp/stderr" || fail "no suggestion for --quantity max_joint_openin"

# 3. Bad input: exit 2, a message naming the folder or file, never a traceback, no PNG.
expect_input_error "$tmp/does_not_exist" "$tmp/does_not_exist"

mkdir "$tmp/no_summary"
cp "$batch/batch_stats.json" "$tmp/no_summary/"
expect_input_error "$tmp/no_summary" "$tmp/no_summary"

mkdir "$tmp/ragged"
cp "$batch/batch_stats.json" "$tmp/ragged/"
{ head -n 3 "$batch/batch_summary.csv"; echo 'a/b/x1,three_span_bridge,b,1,completed,,0.3'; } \
  >"$tmp/ragged/batch_summary.csv"
expect_input_error "$tmp/ragged" "$tmp/ragged/batch_summary.csv"

mkdir "$tmp/not_a_number"
cp "$batch/batch_stats.json" "$tmp/not_a_number/"
head -n 2 "$batch/batch_summary.csv" >"$tmp/not_a_number/batch_summary.csv"
sed -n 3p "$batch/batch_summary.csv" | sed 's/,completed,,\([^,]*\),[^,]*,/,completed,,\1,abc,/' \
  >>"$tmp/not_a_number/batch_summary.csv"
grep -q ',abc,' "$tmp/not_a_number/batch_summary.csv" || fail "could not corrupt the intensity cell"
expect_input_error "$tmp/not_a_number" "$tmp/not_a_number/batch_summary.csv"

mkdir "$tmp/not_a_summary"
printf 'time,girder.u_x\n0,0\n' >"$tmp/not_a_summary/batch_summary.csv"
expect_input_error "$tmp/not_a_summary" "$tmp/not_a_summary/batch_summary.csv"

mkdir "$tmp/bad_json"
cp "$batch/batch_summary.csv" "$tmp/bad_json/"
printf '{"groups": [' >"$tmp/bad_json/batch_stats.json"
expect_input_error "$tmp/bad_json" "$tmp/bad_json/batch_stats.json"

mkdir "$tmp/bad_stats"
cp "$batch/batch_summary.csv" "$tmp/bad_stats/"
printf '{"groups": [{"model": "m", "scale": "big"}]}' >"$tmp/bad_stats/batch_stats.json"
expect_input_error "$tmp/bad_stats" "$tmp/bad_stats/batch_stats.json"

echo "plot_batch_test: ok (${expected[*]})"
