#!/usr/bin/env bash
# A screenshot of a run's report.html (tools/plot_run.py writes it) as headless Chromium renders
# it, to check the page as a reader sees it.
# usage: tools/screenshot_report.sh RUN_FOLDER [OUT.png] [WIDTHxHEIGHT]
# Needs Debian's chromium (apt-get install chromium); the page itself needs nothing but a browser.
set -euo pipefail
folder=${1:?usage: tools/screenshot_report.sh RUN_FOLDER [OUT.png] [WIDTHxHEIGHT]}
out=${2:-$folder/report_screenshot.png}
size=${3:-1280x4000}
report="$folder/report.html"
[ -f "$report" ] || { echo "screenshot_report.sh: no $report (run tools/plot_run.py $folder first)" >&2; exit 2; }
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "screenshot_report.sh: chromium is not installed (apt-get install chromium)" >&2; exit 1; }
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --window-size="${size/x/,}" --screenshot="$out" "file://$(realpath "$report")" 2>/dev/null
echo "$out"
