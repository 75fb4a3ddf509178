#!/usr/bin/env bash
# Checks the Python tools, the Python module, its tests and examples with pyflakes (Debian's python3-pyflakes): unused imports and
# variables, undefined names, and the like, in files git tracks and new ones it does not ignore.
# Lists what it finds and exits 1.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard 'tools/*.py' 'python/*.py' 'tests/python/*.py' 'examples/*.py' 'examples/python/*.py' 'bench/*.py')
python3_with_pyflakes=""
for candidate in /usr/bin/python3 python3; do  # Debian's module is seen by the system python3
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import pyflakes" 2>/dev/null; then
    python3_with_pyflakes=$candidate
    break
  fi
done
if [ -z "$python3_with_pyflakes" ]; then
  echo "pyflakes is not importable: install it with tools/install_dependencies.sh" \
    "(Debian package python3-pyflakes)" >&2
  exit 1
fi
"$python3_with_pyflakes" -m pyflakes "${files[@]}"
