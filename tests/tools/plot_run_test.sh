#!/usr/bin/env bash
# tools/plot_run.py on real runs: the figures exist and are PNGs (plan_motion.png for a 3-D
# scene only); bad input exits 2 cleanly.
# usage: plot_run_test.sh POUND_BINARY REPO_ROOT
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=plot_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/plot_test_common.sh"  # fail, $python, $tmp, check_folder...
pound=$1
root=$2
script="$root/tools/plot_run.py"

# 1. A real run: two girders, a pounding joint link and a restrainer, a node recorder.
run="$tmp/run"
"$pound" run "$root/models/two_girders_joint.json" --out "$run" --quiet ||
  fail "pound run models/two_girders_joint.json failed"
status=0
"$python" "$script" "$run" --dpi 80 >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "plot_run.py exited $status on a good run folder: $(cat "$tmp/stderr")"
expected=(link_forces.png force_penetration.png displacements.png accelerations.png)
[ -f "$run/joints.csv" ] && expected+=(joint_openings.png)
[ -f "$run/energy.csv" ] && expected+=(energy.png)
grep -q '"storeys"\|"piers"' "$run/summary.json" && expected+=(drift_envelopes.png)
# report.html: printed last, one page holding every figure inline and nothing from outside.
report="$run/report.html"
[ "$(tail -n 1 "$tmp/stdout")" = "$report" ] || fail "plot_run.py did not print $report last"
sed -i '$d' "$tmp/stdout"
check_folder "$run" "${expected[@]}"
head -c 15 "$report" | grep -qi '<!doctype html>' || fail "$report is not an HTML page"
figures=$(grep -o 'src="data:image/png;base64,' "$report" | wc -l)
[ "$figures" -eq "$(find "$run" -maxdepth 1 -name '*.png' | wc -l)" ] ||
  fail "$report inlines $figures figures, the folder has $(find "$run" -maxdepth 1 -name '*.png' | wc -l)"
! grep -qiE '(src|href)="(https?:|//|[a-z_]+\.png)' "$report" || fail "$report refers to outside files"
grep -q '<td>joint</td>' "$report" || fail "$report has no row for the link joint"
grep -q 'Energy balance' "$report" || fail "$report has no energy balance"
# Its headings name their units: lengths and times in m and s, forces in N (kg m s).
for heading in 'peak penetration \[m\]' 'time step \[s\]' 'peak force \[N\]'; do
  grep -q "$heading" "$report" || fail "$report has no heading $heading"
done

# 2. The python3 on PATH works too (it starts /usr/bin/python3 if it has no matplotlib).
if command -v python3 >/dev/null 2>&1; then
  rm -f "$run"/*.png
  status=0
  python3 "$script" "$run" --dpi 60 >/dev/null 2>"$tmp/stderr" || status=$?
  [ "$status" -eq 0 ] || fail "python3 $script exited $status: $(cat "$tmp/stderr")"
  is_png "$run/link_forces.png"
fi

# 3. Bad input: exit 2, a message naming the folder or file, never a traceback, no PNG.
mkdir "$tmp/no_summary"
cp "$run/links.csv" "$tmp/no_summary/"
expect_input_error "$tmp/no_summary" "$tmp/no_summary"
expect_input_error "$tmp/does_not_exist" "$tmp/does_not_exist"

mkdir "$tmp/ragged"
cp "$run/summary.json" "$tmp/ragged/"
printf 'time,joint.force,joint.penetration\n0,0,-0.05\n0.1,2\n' >"$tmp/ragged/links.csv"
expect_input_error "$tmp/ragged" "$tmp/ragged/links.csv"

mkdir "$tmp/not_a_number"
cp "$run/summary.json" "$tmp/not_a_number/"
printf 'time,girder.u_x\n0,0\n0.1,abc\n' >"$tmp/not_a_number/nodes.csv"
expect_input_error "$tmp/not_a_number" "$tmp/not_a_number/nodes.csv"

mkdir "$tmp/bad_json"
printf '{"links": [' >"$tmp/bad_json/summary.json"
expect_input_error "$tmp/bad_json" "$tmp/bad_json/summary.json"

# 4. Histories as .npy (recorder files ending in .npy): the same figures.
npy="$tmp/npy"
sed 's/\.csv"/.npy"/' "$root/models/two_girders_joint.json" >"$tmp/npy_model.json"
"$pound" run "$tmp/npy_model.json" --out "$npy" --quiet || fail "pound run with .npy recorders failed"
[ -f "$npy/links.npy" ] || fail "no links.npy written"
"$python" "$script" "$npy" --dpi 60 >/dev/null 2>"$tmp/stderr" ||
  fail "plot_run.py failed on .npy histories: $(cat "$tmp/stderr")"
is_png "$npy/link_forces.png"
is_png "$npy/displacements.png"

# 5. An ensemble run: ensemble.png beside the run's figures; a malformed ensemble.json is bad input.
ensemble="$tmp/ensemble"
"$pound" run "$root/models/two_girders_joint.json" --ensemble 2 --out "$ensemble" --quiet ||
  fail "pound run --ensemble 2 failed"
"$python" "$script" "$ensemble" --dpi 60 >/dev/null 2>"$tmp/stderr" ||
  fail "plot_run.py failed on an ensemble run: $(cat "$tmp/stderr")"
is_png "$ensemble/ensemble.png"
grep -q 'Robustness over the ensemble' "$ensemble/report.html" ||
  fail "the ensemble run's report.html has no robustness table"
mkdir "$tmp/bad_ensemble"
cp "$run/summary.json" "$tmp/bad_ensemble/"
printf '{"quantities": [{"path": "/links/joint/peak_force"}]}' >"$tmp/bad_ensemble/ensemble.json"
expect_input_error "$tmp/bad_ensemble" "$tmp/bad_ensemble/ensemble.json"

# 6. Envelopes and floor spectra (models/adjacent_buildings_outputs.json, 6 s of it): the
# spectra figure, no note about the envelope and spectrum tables, which are no histories.
# pound run of a shortened copy: the warning a cut duration brings (the analysis stops before a
# record's largest acceleration) is expected and dropped; any other warning fails the test.
run_copy() {  # model, out, what
  "$pound" run "$1" --out "$2" --quiet 2>"$tmp/run_stderr" ||
    fail "pound run of $3 failed: $(cat "$tmp/run_stderr")"
  if grep -v "before record '.*' reaches its largest acceleration" "$tmp/run_stderr" | grep -q .; then
    fail "pound run of $3 warned: $(cat "$tmp/run_stderr")"
  fi
}

outputs="$tmp/outputs"
sed 's/"analysis": {"time_step": 0.002}/"analysis": {"time_step": 0.002, "duration": 6}/' \
  "$root/models/adjacent_buildings_outputs.json" >"$tmp/outputs_model.json"
sed -i "s|\.\./ground_motions/|$(cd "$root" && pwd)/ground_motions/|" "$tmp/outputs_model.json"
run_copy "$tmp/outputs_model.json" "$outputs" "the outputs model"
"$python" "$script" "$outputs" --dpi 60 >/dev/null 2>"$tmp/stderr" ||
  fail "plot_run.py failed on envelopes and spectra: $(cat "$tmp/stderr")"
is_png "$outputs/floor_spectra.png"
[ ! -s "$tmp/stderr" ] || fail "plot_run.py noted: $(cat "$tmp/stderr")"

# A model's copy for sections 7 and 8: 3 s of its analysis, its node recorders only (the links'
# many pages are sections 1-6's), its records' paths absolute (the copy lives in $tmp).
node_model() {  # model, copy
  "$python" - "$1" "$2" <<'PY' || fail "could not copy $1"
import json, os, sys
source, copy = sys.argv[1], sys.argv[2]
with open(source, encoding="utf-8") as f:
    model = json.load(f)
model["analysis"]["duration"] = 3.0
model["recorders"] = [r for r in model["recorders"] if r.get("type") == "node"]
folder = os.path.dirname(os.path.abspath(source))
for excitation in model.get("excitations", []):
    for place in (excitation, excitation.get("pair") or {}):
        if "record" in place:
            place["record"] = os.path.normpath(os.path.join(folder, place["record"]))
with open(copy, "w", encoding="utf-8") as f:
    json.dump(model, f, indent=1)
PY
}

# 7. A 3-D scene (models/eccentric_buildings_3d.json): plan_motion.png, the roofs' paths in plan
# and rotations about z, printed and inlined in report.html like the other figures.
space="$tmp/space"
node_model "$root/models/eccentric_buildings_3d.json" "$tmp/space_model.json"
run_copy "$tmp/space_model.json" "$space" "the 3-D model"
grep -q '\.u_rz' "$space/roofs.csv" || fail "the 3-D run recorded no u_rz"
"$python" "$script" "$space" --dpi 60 >"$tmp/stdout" 2>"$tmp/stderr" ||
  fail "plot_run.py failed on a 3-D run: $(cat "$tmp/stderr")"
sed -i '$d' "$tmp/stdout"  # report.html
check_folder "$space" plan_motion.png displacements.png
grep -q 'alt="plan_motion.png"' "$space/report.html" || fail "report.html of the 3-D run lacks plan_motion.png"
[ ! -s "$tmp/stderr" ] || fail "plot_run.py noted on the 3-D run: $(cat "$tmp/stderr")"

# 8. A plane (2-D) scene whose node recorder has the same u_x, u_y, u_rz columns (the three-span
# bridge's pier tops): no plan figure, u_y is the vertical there. The same summary with a u_z
# column (a direction only 3-D scenes have) has one; a non-number in u_rz is bad input.
plane="$tmp/plane"
node_model "$root/models/three_span_bridge.json" "$tmp/plane_model.json"
run_copy "$tmp/plane_model.json" "$plane" "the 2-D model"
grep -q '\.u_y.*\.u_rz' "$plane/pier_tops.csv" || fail "the 2-D run recorded no u_y and u_rz"
"$python" "$script" "$plane" --dpi 60 >/dev/null 2>"$tmp/stderr" ||
  fail "plot_run.py failed on a 2-D run: $(cat "$tmp/stderr")"
is_png "$plane/displacements.png"
# kg, m, s: forces, moments, impulses and energies in N, N·m, N·s.
for heading in 'peak force \[N\]' 'impulse \[N·s\]' 'peak base moment \[N·m\]' \
               'kinetic \[N·m\]' 'peak acceleration (absolute) \[m/s²\]'; do
  grep -q "$heading" "$plane/report.html" || fail "the bridge's report.html has no heading $heading"
done
[ -z "$(find "$plane" -maxdepth 1 -name 'plan_motion*')" ] || fail "plan_motion.png written for a 2-D run"
mkdir "$tmp/columns_3d"
cp "$plane/summary.json" "$tmp/columns_3d/"
printf 'time,deck.u_x,deck.u_y,deck.u_z,deck.u_rz\n0,0,0,0,0\n0.1,0.01,0.02,0,0.001\n' \
  >"$tmp/columns_3d/nodes.csv"
"$python" "$script" "$tmp/columns_3d" --dpi 60 >/dev/null 2>"$tmp/stderr" ||
  fail "plot_run.py failed on a u_z column: $(cat "$tmp/stderr")"
is_png "$tmp/columns_3d/plan_motion.png"
mkdir "$tmp/bad_rotation"
cp "$space/summary.json" "$tmp/bad_rotation/"
printf 'time,f.u_x,f.u_y,f.u_rz\n0,0,0,0\n0.1,0.01,0.02,abc\n' >"$tmp/bad_rotation/nodes.csv"
expect_input_error "$tmp/bad_rotation" "$tmp/bad_rotation/nodes.csv"

echo "plot_run_test: ok (${expected[*]} ensemble.png report.html floor_spectra.png plan_motion.png)"
