#!/usr/bin/env bash
# tools/mutate.py on the bundled models and sets for a fixed budget and seed: every mutant must end
# in a refusal with file and JSON path (exit 2, nothing written), a loud failure (3) that a check
# explains or finite results (0); a crash, a hang, a silent NaN, "an unexpected failure" or another
# exit code fails the test. The slow inputs
# (block_on_belt: 40 s unmutated; the set of the real records: 50 s) are left to longer runs.
# With --options it sweeps every option that takes a value, of every command, with each extreme
# value (0, -1, +-1e308, NaN, +-inf, 1e-320, text, empty, 2^31, hex, a list) beside a valid
# invocation: a usage error naming the option (exit 1) and the same contract otherwise; the whole
# sweep takes about 40 s on two cores, the budget bounds it on a slower machine.
# usage: mutate_test.sh POUND_BINARY REPO_ROOT [BUDGET_SECONDS] [--options]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 POUND_BINARY REPO_ROOT [BUDGET_SECONDS] [--options]" >&2
  exit 1
fi
pound=$1
root=$2
budget=${3:-60}
python=python3
command -v "$python" >/dev/null 2>&1 || python=/usr/bin/python3
keep=$(mktemp -d)
trap 'rm -rf "$keep"' EXIT
if [ "${4:-}" = "--options" ]; then
  mode=(--options)
  replay="python3 tools/mutate.py --options --binary $pound --verbose"
else
  mode=(--keep "$keep/keep" --exclude models/block_on_belt.json sets/three_span_bridge_records.json)
  replay="python3 tools/mutate.py --binary $pound --seed 1 --budget-seconds $budget --keep DIR --exclude models/block_on_belt.json sets/three_span_bridge_records.json"
fi
status=0
"$python" "$root/tools/mutate.py" --binary "$pound" --seed 1 --budget-seconds "$budget" --jobs 2 \
  "${mode[@]}" || status=$?
if [ "$status" -ne 0 ]; then
  echo "FAIL: tools/mutate.py ${4:-} found contract breaks (exit $status); replay with $replay" >&2
fi
exit "$status"
