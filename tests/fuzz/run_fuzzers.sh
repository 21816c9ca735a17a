#!/bin/bash
# Builds the libFuzzer targets (tests/fuzz/*.cpp) with clang in build-fuzz and runs each for a
# bounded time, seeded from the bundled files and from tests/fuzz/corpus/<target>/ (structure-
# aware seeds: aliases, anchors, merge keys, tags, duplicate keys, deep trees, oversized fields;
# and every input behind an earlier finding), with a dictionary of YAML or MJCF/URDF tokens.
# Fails on any crash, sanitizer report, leak, out-of-memory or timeout; the input that caused it
# is left in build-fuzz/artifacts/. Keep it as a regression input:
#   cp build-fuzz/artifacts/<target>-crash-* tests/fuzz/corpus/<target>/
# (CTest replays every corpus in every build: <target>_corpus, tests/fuzz/replay_corpus.cpp.)
# Usage: tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
#   CI runs 30 s per target; the long run is tests/fuzz/run_fuzzers.sh 600 (10 min per target).
set -uo pipefail
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
SECONDS_EACH=${1:-60}
shift || true
BUILD=${COSIM_FUZZ_BUILD_DIR:-$ROOT/build-fuzz}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# libFuzzer comes with clang (Debian 12: clang-14 and libclang-rt-14-dev); install if missing.
if ! command -v clang++ >/dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null |
    grep -q "install ok installed"; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "fuzz: installing clang libclang-rt-14-dev"
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq clang \
    libclang-rt-14-dev >/dev/null || exit 3
fi

CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOSIM_FUZZ=ON \
  -DCOSIM_WITH_SIM=ON >/dev/null || exit 3
cmake --build "$BUILD" -j"$JOBS" --target fuzzers || exit 3

# Seeds: the bundled files each parser is meant to read, and the target's kept corpus.
seeds() {
  case "$1" in
    fuzz_scenario) ls experiments/scenarios/*.yaml ;;
    fuzz_sweep) ls experiments/sweeps/*.yaml ;;
    fuzz_movingai_map) ls experiments/maps/*.map tests/data/movingai/*.map ;;
    fuzz_movingai_scen) ls experiments/maps/*.scen tests/data/movingai/*.scen ;;
    fuzz_urdf) ls models/*.urdf ;;
    fuzz_world_fragment) ls tests/fuzz/corpus/fuzz_world_fragment/*.xml ;;
    fuzz_flight_log_csv | fuzz_usd_log) ;;  # their kept corpus only
    fuzz_reference_file) ls experiments/references/*.csv ;;
  esac
  [ -d "tests/fuzz/corpus/$1" ] && find "tests/fuzz/corpus/$1" -type f
}
dictionary() {
  case "$1" in
    fuzz_scenario | fuzz_sweep) echo "-dict=$ROOT/tests/fuzz/yaml.dict" ;;
    fuzz_urdf | fuzz_world_fragment) echo "-dict=$ROOT/tests/fuzz/mjcf.dict" ;;
  esac
}

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for t in fuzz_scenario fuzz_sweep fuzz_movingai_map fuzz_movingai_scen fuzz_urdf fuzz_urdf_tree \
      fuzz_world_fragment fuzz_flight_log_csv fuzz_usd_log fuzz_reference_file; do
    [ -x "$BUILD/tests/fuzz/$t" ] && targets+=("$t")
  done
fi

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$ROOT/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$BUILD/artifacts"
failed=()
for t in "${targets[@]}"; do
  corpus="$BUILD/corpus/$t"
  mkdir -p "$corpus"
  # Seeds are copied under names of their own (a kept corpus file may share a bundled name).
  for f in $(seeds "$t"); do cp -f "$f" "$corpus/seed-$(echo "$f" | tr '/' '_')"; done
  echo "fuzz: $t for ${SECONDS_EACH} s (corpus $(ls "$corpus" | wc -l) files)"
  # The corpus directory grows between runs (kept in build-fuzz, never in the source tree).
  # shellcheck disable=SC2046  # the dictionary option is one word or none
  if ! "$BUILD/tests/fuzz/$t" "$corpus" $(dictionary "$t") -max_total_time="$SECONDS_EACH" -timeout=10 \
      -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="$BUILD/artifacts/$t-" >"$BUILD/artifacts/$t.log" 2>&1; then
    failed+=("$t")
    echo "fuzz: $t FAILED; log: $BUILD/artifacts/$t.log" >&2
    grep -E "ERROR|SUMMARY|Test unit written|runtime error" "$BUILD/artifacts/$t.log" | head -20 >&2
  else
    grep -E "stat::number_of_executed_units|cov:" "$BUILD/artifacts/$t.log" | tail -2
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets, no findings"
