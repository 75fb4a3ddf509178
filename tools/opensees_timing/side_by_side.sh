#!/usr/bin/env bash
# Times OpenSees and pound side by side on the bundled three-span bridge and the two SDOF girders
# (issue 20), in alternating rounds on one machine, after checking that the two programs build the
# same bridge (its displacements until the first impact).
#
#   tools/opensees_timing/side_by_side.sh OPENSEES BUILD_DIR [ROUNDS]
#
# OPENSEES: the Tcl interpreter built from OpenSees' source (docs/performance.md says how; nothing
# of OpenSees is in this repository). BUILD_DIR: pound's Release build (its src/pound and
# bench/pound_bench). ROUNDS (default 5): each round runs OpenSees on each script three times (the
# best of the three; OpenSees writes what a script puts to stderr) and pound_bench once (the best
# of its 7 solves). Prints each round's times and ratios, then the medians. Both time the solve
# alone: OpenSees its `analyze`, pound its run without histories (the model read and built,
# restitution calibrated, before the clock starts).
#
# Two settings of OpenSees: `plain`, its textbook recipe (Newton with a new tangent every
# iteration, BandGeneral, NormDispIncr 1e-12), and `fast`, to_tcl.py's defaults, the fastest
# found (ModifiedNewton, ProfileSPD, NormUnbalance 1e-2 N). Both give pound's displacements of the
# bridge to 1.5e-14 m before the first impact (the check below runs `fast`).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
if [ $# -lt 2 ]; then
  echo "usage: $0 OPENSEES BUILD_DIR [ROUNDS]" >&2
  exit 1
fi
opensees="$1"
build="$(cd "$2" && pwd)"
rounds="${3:-5}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

plain=(--test "NormDispIncr 1e-12 25" --system BandGeneral --algorithm Newton)
for model in three_span_bridge:bridge two_sdof_girders:girders; do
  name=${model#*:}
  # expanded beside nothing: its record path is made relative to where it is written
  "$build/src/pound" expand "$repo/models/${model%:*}.json" --out "$work/$name.json" >/dev/null
  python3 "$here/to_tcl.py" "$work/$name.json" "$work/${name}_fast.tcl"
  python3 "$here/to_tcl.py" "$work/$name.json" "$work/${name}_plain.tcl" "${plain[@]}"
done

echo "== the same bridge: x displacements of both abutment girder ends and a pier top"
nodes=bridge.g0.n0,bridge.p1.top,bridge.g2.n4
python3 "$here/to_tcl.py" "$work/bridge.json" "$work/bridge_check.tcl" --record-nodes "$nodes"
python3 - "$work/bridge.json" "$work/bridge_check.json" "$nodes" <<'PY'
import json, sys
model = json.load(open(sys.argv[1]))
model["recorders"] = [
    {"type": "node", "nodes": sys.argv[3].split(","), "file": "nodes.csv"},
    {"type": "link", "file": "contacts.csv",
     "links": ["bridge.a0.joint", "bridge.joint1", "bridge.joint2", "bridge.a1.joint"]}]
json.dump(model, open(sys.argv[2], "w"))
PY
"$build/src/pound" run "$work/bridge_check.json" --out "$work/pound_check" >/dev/null
(cd "$work" && "$opensees" bridge_check.tcl >"$work/check.log" 2>&1)
grep -m1 '^periods' "$work/check.log" || true
python3 "$here/compare.py" "$work/pound_check/nodes.csv" "$work/pound_check/contacts.csv" \
  "$work/bridge_check.disp.out"

opensees_ms() {  # script: the best solve_ms of three processes
  local best=inf ms
  for _ in 1 2 3; do
    ms=$(cd "$work" && "$opensees" "$1" 2>&1 | sed -n 's/.*ok 0 solve_ms \([0-9.]*\).*/\1/p')
    [ -n "$ms" ] || { echo "OpenSees failed on $1" >&2; exit 3; }
    best=$(python3 -c "print(min($ms, float('$best')))")
  done
  echo "$best"
}

show_row() {  # label, the ten numbers of a row of $work/ratios after its round
  # shellcheck disable=SC2086  # the numbers are the format's arguments, split on purpose
  printf "%6s  %8.1f / %6.1f  %6.2f  %4.1fx %4.1fx | %8.2f / %5.2f  %5.3f  %4.1fx %4.1fx\n" "$1" $2
}

echo "== solve times, ms (OpenSees best of 3 processes, pound best of 7 solves)"
echo "          bridge, 16,667 steps                   | two SDOF girders, per 4,000 steps"
echo " round  OpenSees plain / fast   pound  ratios     | OpenSees plain / fast  pound  ratios"
: >"$work/ratios"
for round in $(seq "$rounds"); do
  times=()
  for script in bridge_plain bridge_fast girders_plain girders_fast; do
    times+=("$(opensees_ms "$script.tcl")")
  done
  "$build/bench/pound_bench" --benchmark_filter='three_span_bridge_solve|two_sdof_girders_solve' \
    --benchmark_format=json 2>/dev/null >"$work/bench.json"
  python3 - "$work/bench.json" "$work/girders_fast.tcl" "$round" "${times[@]}" \
    >>"$work/ratios" <<'PY'
import json, re, sys
bench = {b["name"].split("/")[0]: b for b in json.load(open(sys.argv[1]))["benchmarks"]}
steps = int(re.search(r"analyze (\d+)", open(sys.argv[2]).read()).group(1))
bridge_plain, bridge_fast, girders_plain, girders_fast = map(float, sys.argv[4:8])
girders_plain, girders_fast = girders_plain * 4000 / steps, girders_fast * 4000 / steps
pound_bridge = bench["three_span_bridge_solve"]["ms_per_run"]
pound_girders = bench["two_sdof_girders_solve"]["ms_per_reference_run"]
print(sys.argv[3], bridge_plain, bridge_fast, pound_bridge, bridge_plain / pound_bridge,
      bridge_fast / pound_bridge, girders_plain, girders_fast, pound_girders,
      girders_plain / pound_girders, girders_fast / pound_girders)
PY
  show_row "$round" "$(tail -1 "$work/ratios" | cut -d' ' -f2-)"
done
show_row median "$(python3 - "$work/ratios" <<'PY'
import statistics, sys
rows = [list(map(float, line.split())) for line in open(sys.argv[1])]
print(*(statistics.median(r[k] for r in rows) for k in range(1, 11)))
PY
)"
