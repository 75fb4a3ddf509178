#!/usr/bin/env bash
# tools/plot_block_belt.py on synthetic block-belt CSVs: the four figures exist and are PNGs;
# bad input exits 2 cleanly and writes nothing. The pound binary is not run (the data is made
# here, so the test stays fast); its argument is taken for the same calling convention as the
# other tools tests.
# usage: plot_block_belt_test.sh POUND_BINARY REPO_ROOT
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=plot_test_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/plot_test_common.sh"  # fail, $python, $tmp, check_folder...
root=$2
script="$root/tools/plot_block_belt.py"

figures=(fig13_spring_elongation.png fig14_centroid_x.png fig15_centroid_y.png
         fig16_friction_ratio.png)

check_figures() {  # folder: the four PNGs and no other, each printed, one line each, no leftovers
  check_folder "$1" "${figures[@]}"
  [ "$(find "$1" -maxdepth 1 -name '*.png' | wc -l)" -eq 4 ] || fail "not 4 PNGs in $1"
}

# 1. Synthetic data shaped like `pound verify block-belt --out`: the default sweep's sixteen
#    speeds, one stick-slip point and one tumbling point, 200 history samples per speed.
data="$tmp/data"
mkdir "$data"
"$python" - "$data" <<'EOF'
import math, sys
folder = sys.argv[1]
speeds = [1e-3, 1e-2, 3e-2, 1e-1, 3e-1, 1.0, 3.0, 10.0, 30.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8]
with open(f"{folder}/block_belt_sweep.csv", "w") as sweep, \
        open(f"{folder}/block_belt_histories.csv", "w") as histories:
    sweep.write("dimensionless_speed,belt_speed,friction_ratio,stick_fraction,stick_slip_cycles,"
                "stick_slip,lift_fraction,tumbling,peak_lift,steps,time_step,run_time_s\n")
    histories.write("dimensionless_speed,time_over_period,elongation,centroid_x,centroid_y\n")
    for pi in speeds:
        ratio = 1.0 - 0.3 / (1.0 + math.exp(-(math.log10(pi) - 2.0)))
        stick_slip = int(pi == 1e-2)
        tumbling = int(pi == 1e8)
        sweep.write(f"{pi},{pi * 0.01},{ratio},{0.5 * stick_slip},{3 * stick_slip},{stick_slip},"
                    f"{0.1 * tumbling},{tumbling},{1e-4 * tumbling},4000,1e-5,0.25\n")
        for k in range(200):
            t = 4.0 * k / 199
            histories.write(f"{pi},{t},{ratio + (1 - ratio) * math.cos(2 * math.pi * t)},"
                            f"{(1 - ratio) * math.sin(2 * math.pi * t)},"
                            f"{-0.01 + 0.002 * math.sin(7 * t)}\n")
EOF
status=0
"$python" "$script" "$data" --dpi 60 >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "plot_block_belt.py exited $status on good data: $(cat "$tmp/stderr")"
! grep -q Traceback "$tmp/stderr" || fail "traceback on good data: $(cat "$tmp/stderr")"
check_figures "$data"

# 2. --out and --speeds (1e5 names 100000); the python3 on PATH works too (it starts
#    /usr/bin/python3 if it has no matplotlib).
interpreter=$python
command -v python3 >/dev/null 2>&1 && interpreter=python3
status=0
"$interpreter" "$script" "$data" --out "$tmp/chosen" --speeds 1e5,0.001,3 --dpi 60 \
  >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
[ "$status" -eq 0 ] || fail "$interpreter plot_block_belt.py --out --speeds exited $status: $(cat "$tmp/stderr")"
check_figures "$tmp/chosen"

status=0
"$python" "$script" "$data" --out "$tmp/usage" --speeds 1e5,abc >/dev/null 2>"$tmp/stderr" || status=$?
[ "$status" -eq 1 ] || fail "expected exit 1 for --speeds 1e5,abc, got $status: $(cat "$tmp/stderr")"
[ ! -e "$tmp/usage" ] || fail "--speeds 1e5,abc created its --out folder"

# 3. Bad input: exit 2, a message naming the file, never a traceback, no PNG anywhere. This
#    replaces the common expect_input_error: the script is given --out and more arguments, and
#    must name itself and print nothing.
expect_input_error() {  # folder, text the message must contain, more arguments...
  local folder=$1 text=$2
  shift 2
  local status=0
  "$python" "$script" "$folder" --out "$tmp/out" "$@" >"$tmp/stdout" 2>"$tmp/stderr" || status=$?
  [ "$status" -eq 2 ] || fail "expected exit 2 for $folder $*, got $status: $(cat "$tmp/stderr")"
  grep -q "^plot_block_belt.py: " "$tmp/stderr" || fail "message without the script's name: $(cat "$tmp/stderr")"
  grep -qF "$text" "$tmp/stderr" || fail "message for $folder $* does not name $text: $(cat "$tmp/stderr")"
  ! grep -q Traceback "$tmp/stderr" || fail "traceback for $folder: $(cat "$tmp/stderr")"
  [ ! -s "$tmp/stdout" ] || fail "output printed for $folder: $(cat "$tmp/stdout")"
  ! find "$folder" "$tmp/out" -maxdepth 1 -name '*.png' 2>/dev/null | grep -q . ||
    fail "PNGs written for $folder $*"
}
expect_input_error "$tmp/does_not_exist" "$tmp/does_not_exist"

bad() {  # a copy of the good data, without PNGs
  mkdir "$tmp/$1"
  cp "$data"/*.csv "$tmp/$1/"
}

bad no_histories
rm "$tmp/no_histories/block_belt_histories.csv"
expect_input_error "$tmp/no_histories" "$tmp/no_histories/block_belt_histories.csv"

bad missing_column  # the histories without centroid_y
cut -d, -f1-4 "$data/block_belt_histories.csv" >"$tmp/missing_column/block_belt_histories.csv"
expect_input_error "$tmp/missing_column" "centroid_y"
grep -qF "$tmp/missing_column/block_belt_histories.csv" "$tmp/stderr" ||
  fail "missing column message does not name the file: $(cat "$tmp/stderr")"

bad not_a_number  # friction_ratio of the third sweep row
sed -i '4s/^\([^,]*\),\([^,]*\),[^,]*,/\1,\2,abc,/' "$tmp/not_a_number/block_belt_sweep.csv"
grep -q ',abc,' "$tmp/not_a_number/block_belt_sweep.csv" || fail "could not corrupt friction_ratio"
expect_input_error "$tmp/not_a_number" "$tmp/not_a_number/block_belt_sweep.csv"
grep -qF "friction_ratio" "$tmp/stderr" || fail "non-numeric message does not name the column"

bad empty_sweep
head -n 1 "$data/block_belt_sweep.csv" >"$tmp/empty_sweep/block_belt_sweep.csv"
expect_input_error "$tmp/empty_sweep" "$tmp/empty_sweep/block_belt_sweep.csv"

bad bad_flag
sed -i '2s/^\(\([^,]*,\)\{5\}\)0,/\12,/' "$tmp/bad_flag/block_belt_sweep.csv"
expect_input_error "$tmp/bad_flag" "stick_slip"

bad absent_speed
expect_input_error "$tmp/absent_speed" "$tmp/absent_speed/block_belt_histories.csv" --speeds 1e5,2e5
grep -qF "Pi = 200000" "$tmp/stderr" || fail "--speeds message does not name 2e5: $(cat "$tmp/stderr")"

echo "plot_block_belt_test: ok (${figures[*]})"
