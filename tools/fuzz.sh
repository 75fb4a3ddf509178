#!/usr/bin/env bash
# Fuzzes the readers: builds the libFuzzer targets (build-fuzz, clang, ASan + UBSan) if needed and
# runs each for SECONDS (default 20) from a copy of its seed corpus, fuzz/corpus/<target>, plus the
# real records in ../shared/ground_motions for the record readers when that folder exists (as in
# CI). Exits non-zero if any target finds a crash, a hang (> 5 s per input), memory over 2 GB, a
# leak, a sanitizer report or an exception other than InputError; the input that did it is left in
# build-fuzz/findings/ (replay: build-fuzz/fuzz/fuzz_<target> FILE).
#   tools/fuzz.sh            # about a minute, as in CI
#   tools/fuzz.sh 3600       # an hour per target
set -euo pipefail
seconds=${1:-20}
cd "$(dirname "$0")/.."
build=build-fuzz
targets=(model set at2 columns)

if [ ! -f "$build/build.ninja" ]; then
  CXX=clang++ cmake -S . -B "$build" -G Ninja -DPOUND_FUZZ=ON -DPOUND_BUILD_TESTS=OFF \
    -DPOUND_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build"

extra_seeds=()
if [ -d ../shared/ground_motions ]; then extra_seeds=(../shared/ground_motions); fi

status=0
mkdir -p "$build/findings"
for target in "${targets[@]}"; do
  work="$build/fuzz-run/$target"
  rm -rf "$work" && mkdir -p "$work"
  cp -r "fuzz/corpus/$target" "$work/corpus"  # libFuzzer adds what it finds to the first folder
  seeds=()
  # The real records are seeds for their headers; cut to 16 kB so mutating them stays fast.
  if [ "$target" = at2 ] || [ "$target" = columns ]; then seeds=("${extra_seeds[@]}"); fi
  dict=fuzz/record.dict
  if [ "$target" = model ] || [ "$target" = set ]; then dict=fuzz/model.dict; fi
  echo "fuzz_$target: ${seconds} s"
  if "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
      -max_len=16384 -dict="$dict" -print_final_stats=1 -artifact_prefix="$build/findings/$target-" \
      "$work/corpus" "${seeds[@]}" >"$work/log.txt" 2>&1; then
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/log.txt" | sed 's/^/  /'
  else
    status=1
    echo "fuzz_$target FOUND A PROBLEM (log: $work/log.txt):"
    grep -E -A30 "ERROR|==[0-9]+==|uncaught|deadly signal|timeout" "$work/log.txt" | head -60
  fi
done
exit $status
