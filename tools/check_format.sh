#!/usr/bin/env bash
# Checks that every C++ file of the repository is formatted by the checked-in .clang-format
# (Debian's clang-format). Lists the files that are not and exits 1; `tools/check_format.sh --fix`
# formats them in place. New files count before they are added: git's untracked files that
# .gitignore does not exclude are checked too.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.hpp')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
status=0
for file in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$file" >/dev/null 2>&1; then
    echo "not formatted: $file (tools/check_format.sh --fix)"
    status=1
  fi
done
exit $status
