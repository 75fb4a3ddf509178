#!/usr/bin/env bash
# tools/mutate.py on the bundled models and sets for a fixed budget and seed: every mutant must end
# in a refusal with file and JSON path (exit 2, nothing written), a loud failure (3) that a check
# explains or finite results (0); a crash, a hang, a silent NaN, "an unexpected failure" or another
# exit code fails the test. The slow inputs
# (block_on_belt: 40 s unmutated; the set of the real records: 50 s) are left to longer runs.
# usage: mutate_test.sh POUND_BINARY REPO_ROOT [BUDGET_SECONDS]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 POUND_BINARY REPO_ROOT [BUDGET_SECONDS]" >&2
  exit 1
fi
pound=$1
root=$2
budget=${3:-60}
python=python3
command -v "$python" >/dev/null 2>&1 || python=/usr/bin/python3
keep=$(mktemp -d)
trap 'rm -rf "$keep"' EXIT
status=0
"$python" "$root/tools/mutate.py" --binary "$pound" --seed 1 --budget-seconds "$budget" --jobs 2 \
  --keep "$keep/keep" --exclude models/block_on_belt.json sets/three_span_bridge_records.json || status=$?
if [ "$status" -ne 0 ]; then
  echo "FAIL: tools/mutate.py found contract breaks (exit $status); replay with" \
    "python3 tools/mutate.py --binary $pound --seed 1 --budget-seconds $budget --keep DIR --exclude models/block_on_belt.json sets/three_span_bridge_records.json" >&2
fi
exit "$status"
