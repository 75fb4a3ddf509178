#!/usr/bin/env bash
# tools/mutate.py --options: every option that takes a value, of every command, given each extreme
# value (0, -1, +-1e308, NaN, +-inf, 1e-320, text, empty, 2^31, hex, a list) beside a valid
# invocation: a usage error naming the option (exit 1), a refusal or loud failure with an "error:"
# line (2, 3; nothing written on 1 or 2) or finite results (0). A crash, a hang, a NaN in a
# completed result, "an unexpected failure" or another exit code fails the test. The whole sweep
# takes about 40 s on two cores; the budget bounds it on a slower machine.
# usage: mutate_options_test.sh POUND_BINARY REPO_ROOT [BUDGET_SECONDS]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 POUND_BINARY REPO_ROOT [BUDGET_SECONDS]" >&2
  exit 1
fi
pound=$1
root=$2
budget=${3:-90}
python=python3
command -v "$python" >/dev/null 2>&1 || python=/usr/bin/python3
status=0
"$python" "$root/tools/mutate.py" --options --binary "$pound" --seed 1 --budget-seconds "$budget" \
  --jobs 2 || status=$?
if [ "$status" -ne 0 ]; then
  echo "FAIL: tools/mutate.py --options found contract breaks (exit $status); replay with" \
    "python3 tools/mutate.py --options --binary $pound --verbose" >&2
fi
exit "$status"
