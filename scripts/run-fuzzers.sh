#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, fuzz/CMakeLists.txt) and runs each one
# for a bounded time. Any crash, sanitizer report, timeout or out-of-memory fails the run;
# the offending input is left under $BUILD/artifacts/<target>/ (copy it to
# tests/corpus/<target>/ once fixed, so the replay test keeps it fixed).
#
#   scripts/run-fuzzers.sh [SECONDS_PER_TARGET] [TARGET...]
#
# SECONDS_PER_TARGET defaults to 60; TARGETs default to all four (scene_file obj_file
# image_file pipeline). Environment: FUZZ_BUILD_DIR (default build-fuzz), FUZZ_JOBS (build
# parallelism, default nproc), FUZZ_ARGS (extra libFuzzer flags, e.g. "-fork=1 -ignore_crashes=1"
# to keep going after a crash and collect every crasher), FUZZ_SEED (libFuzzer's -seed, default
# 1: with the same seeds, an empty working corpus and the same binary, a run repeats the inputs
# an earlier run with that seed tried, as far as its time allows, so CI tries what a local run
# already passed plus whatever a code change makes it reach; 0 lets libFuzzer pick). The working corpus, $BUILD/corpus/<target>/, grows across
# runs; each run also reads seeds from tests/corpus/<target>/ and the repository's assets.
# A summary line per target (executions, corpus size, coverage) goes to $BUILD/fuzz-summary.txt.
# FUZZ_WERROR (ON|OFF) sets TWINRASTER_WERROR, -Werror for the project's code: ON when the CI
# environment variable is set, else OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_file obj_file image_file pipeline)
build=${FUZZ_BUILD_DIR:-build-fuzz}
case "${CI:-}" in ""|false|0) werror=OFF ;; *) werror=ON ;; esac
werror=${FUZZ_WERROR:-$werror}
jobs=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}

for tool in clang clang++; do
  command -v "$tool" >/dev/null || { echo "run-fuzzers: $tool not found (scripts/install-deps.sh installs it)" >&2; exit 2; }
done

# A build folder already configured with the fuzz targets (make sanitize's build-sanitize, as
# CI passes) is reused as it is: one clang ASan + UBSan build serves the tests and the fuzzers.
if grep -q '^TWINRASTER_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "run-fuzzers: building ${targets[*]} in $build (configured already)"
else
  echo "run-fuzzers: building ${targets[*]} in $build (clang, ASan + UBSan)"
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTWINRASTER_FUZZ=ON \
    -DTWINRASTER_SANITIZE=ON -DTWINRASTER_BUILD_GUI=OFF -DTWINRASTER_BUILD_BENCH=OFF \
    -DTWINRASTER_WERROR="$werror" >/dev/null
fi
build_targets=()
for t in "${targets[@]}"; do build_targets+=(--target "fuzz_$t"); done
cmake --build "$build" -j "$jobs" "${build_targets[@]}"

# Seeds: copies, so libFuzzer never writes into the source tree.
seed_dir() {
  local target=$1 dir="$build/seeds/$1"
  rm -rf "$dir"
  mkdir -p "$dir"
  case $target in
    scene_file) cp assets/scenes/*.json tests/scene/data_scenes/*.json "$dir"/ ;;
    obj_file)
      cp assets/models/*.obj tests/scene/data/*.obj tests/scene/data_scenes/models/*.obj "$dir"/
      if [ -d /usr/share/assimp/models ]; then
        find /usr/share/assimp/models -iname '*.obj' -size -64k -exec cp {} "$dir"/ \;
      fi ;;
    image_file) cp assets/textures/*.png tests/scene/data_scenes/*.png "$dir"/ ;;
    pipeline) ;;
  esac
  cp tests/corpus/"$target"/* "$dir"/ 2>/dev/null || true
  rm -f "$dir"/README.md
  echo "$dir"
}

# Longest input tried per target (bytes): enough for every seed's structure, short enough
# that one execution stays in the sub-millisecond range.
max_len() {
  case $1 in
    scene_file | obj_file) echo 32768 ;;
    image_file) echo 65536 ;;
    pipeline) echo 2048 ;;
  esac
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
summary="$build/fuzz-summary.txt"
: >"$summary"
status=0
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  artifacts="$build/artifacts/$t/"
  mkdir -p "$corpus" "$artifacts"
  seeds=$(seed_dir "$t")
  dict=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
  log="$build/fuzz-$t.log"
  echo "run-fuzzers: fuzz_$t for ${seconds} s (log: $log)"
  set +e
  "$build/fuzz/fuzz_$t" "$corpus" "$seeds" "${dict[@]}" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=30 \
    -rss_limit_mb=3072 -max_len="$(max_len "$t")" -artifact_prefix="$artifacts" -print_final_stats=1 \
    ${FUZZ_ARGS:-} >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  [ -z "$runs" ] && runs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')  # -fork mode
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  files=$(find "$corpus" -type f | wc -l)
  line="$t: exit $rc, ${seconds} s, ${runs:-?} executions, coverage ${cov:-?} edges, corpus $files files"
  echo "$line" | tee -a "$summary"
  if [ $rc -ne 0 ]; then
    status=1
    echo "run-fuzzers: fuzz_$t FAILED; the input is in $artifacts, the report in $log:" >&2
    grep -E 'ERROR|runtime error|SUMMARY|terminate|what\(\)' "$log" | head -20 >&2 || true
  fi
done
exit $status
