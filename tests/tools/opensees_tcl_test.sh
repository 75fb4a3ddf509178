#!/usr/bin/env bash
# tools/opensees_timing/to_tcl.py without OpenSees: the scripts it writes for the two timed models
# hold the structure pound builds (free DOFs, total mass, one element per link with the law's
# material), and a model it does not cover, or a file it cannot read, exits 2 naming the file.
# usage: opensees_tcl_test.sh POUND_BINARY REPO_ROOT
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=tool_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/tool_test_common.sh"  # the arguments, fail, $tmp
python=python3
pound=$1
root=$2
script="$root/tools/opensees_timing/to_tcl.py"

# counts.py TCL: free DOFs (nodes x ndf less fixed flags), total mass of the DOFs along x, and
# the number of each uniaxial material.
cat >"$tmp/counts.py" <<'EOF'
import collections, sys
dofs = fixed = 0
mass = 0.0
materials = collections.Counter()
links = 0
for line in open(sys.argv[1]):
    words = line.split()
    if not words:
        continue
    if words[0] == "model":
        ndf = int(words[words.index("-ndf") + 1])
    elif words[0] == "node":
        dofs += ndf
    elif words[0] == "fix":
        fixed += sum(map(int, words[2:]))
    elif words[0] == "mass":
        mass += float(words[2])
    elif words[0] == "uniaxialMaterial" and int(words[2]) > 10000:
        materials[words[1]] += 1
    elif words[0] == "element" and words[1] == "zeroLength" and int(words[2]) > 10000:
        links += 1
kinds = " ".join(f"{k}:{v}" for k, v in sorted(materials.items()))
print(dofs - fixed, round(mass, 6), links, kinds)
EOF

convert() {  # model name, expected counts line
  "$pound" expand "$root/models/$1.json" --out "$tmp/$1.json" >/dev/null || fail "pound expand $1"
  "$python" "$script" "$tmp/$1.json" "$tmp/$1.tcl" >"$tmp/stdout" 2>"$tmp/stderr" ||
    fail "to_tcl.py failed on $1: $(cat "$tmp/stderr")"
  local counts
  counts=$("$python" "$tmp/counts.py" "$tmp/$1.tcl")
  [ "$counts" = "$2" ] || fail "$1: expected '$2', the script holds '$counts'"
  grep -q "analyze $3 " "$tmp/$1.tcl" || fail "$1: expected analyze $3 steps"
  [ -s "$tmp/$1.acc" ] || fail "$1: no record values written beside the script"
}
# The bridge: 59 DOFs as pound numbers them (summary.json's dofs); mass: girders 100 m x 25 t/m,
# piers 2 x 8 m x 7.5 t/m, backwalls 2 x 50 t; 20 links: 6 bearings x (Steel01 + Elastic), 4
# Hertzdamp contacts, 2 restrainers, 2 backfills.
convert three_span_bridge \
  "59 2720000.0 20 Elastic:6 ElasticPPGap:2 Hertzdamp:4 HyperbolicGapMaterial:2 Steel01:6" 16667
convert two_sdof_girders "2 600000.0 1 ViscoelasticGap:1" 15000
grep -q 'Hertzdamp 10005 10000000000.0 0.97' "$tmp/three_span_bridge.tcl" ||
  fail "the bridge's joint: expected xi_bar = 0.97... (pound's exact calibration of e = 0.6)"
grep -q 'HyperbolicGapMaterial 10015 500000000.0 500000000.0 0.832' "$tmp/three_span_bridge.tcl" ||
  fail "the bridge's backfill: expected R_f = 1 - 1.05e7 / (5e8 x 0.125) = 0.832"

# Not covered, or not readable: exit 2 with the file named, nothing written.
expect_refused() {  # model file, words of the message
  local status=0
  "$python" "$script" "$1" "$tmp/refused.tcl" >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
  [ "$status" -eq 2 ] || fail "expected exit 2 on $1, got $status: $(cat "$tmp/stderr")"
  grep -q "$1" "$tmp/stderr" || fail "the message does not name $1: $(cat "$tmp/stderr")"
  grep -q "$2" "$tmp/stderr" || fail "the message does not say '$2': $(cat "$tmp/stderr")"
  ! grep -q Traceback "$tmp/stderr" || fail "a traceback on $1"
  [ ! -e "$tmp/refused.tcl" ] || fail "a script was written for $1"
  [ ! -e "$tmp/refused.acc" ] || fail "a record file was written for $1"
}
"$pound" expand "$root/models/adjacent_buildings_yielding.json" --out "$tmp/takeda.json" >/dev/null
expect_refused "$tmp/takeda.json" "not covered"
echo '{"nodes": [' >"$tmp/broken.json"
expect_refused "$tmp/broken.json" "cannot be read as JSON"
expect_refused "$tmp/missing.json" "cannot be read"
# refused after the record is read (the integrator is checked last): still nothing written
"$python" - "$tmp/two_sdof_girders.json" "$tmp/refused.json" <<'EOF'
import json, sys
model = json.load(open(sys.argv[1]))
model["analysis"]["integrator"] = {"type": "newmark", "beta": 0.3025, "gamma": 0.6}
json.dump(model, open(sys.argv[2], "w"))
EOF
expect_refused "$tmp/refused.json" "average acceleration"
# a wrong type, and no mass at a Kelvin-Voigt link's ends (its damping would divide by zero)
"$python" - "$tmp/two_sdof_girders.json" "$tmp/wrong_type.json" "$tmp/no_mass.json" <<'EOF'
import json, sys
model = json.load(open(sys.argv[1]))
json.dump(dict(model, nodes=5), open(sys.argv[2], "w"))
json.dump(dict(model, masses=[]), open(sys.argv[3], "w"))
EOF
expect_refused "$tmp/wrong_type.json" "TypeError"
expect_refused "$tmp/no_mass.json" "ZeroDivisionError"
echo "opensees_tcl: ok"
