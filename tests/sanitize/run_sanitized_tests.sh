#!/bin/bash
# Builds cosim with AddressSanitizer + UndefinedBehaviorSanitizer (COSIM_SANITIZE=ON) in
# build-asan and runs the whole test suite under them. Any report fails the run: UBSan aborts
# (-fno-sanitize-recover), ASan aborts on the first error, LeakSanitizer fails at exit.
# Usage: tests/sanitize/run_sanitized_tests.sh [extra ctest arguments, e.g. -E pattern]
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
BUILD=${COSIM_ASAN_BUILD_DIR:-$ROOT/build-asan}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# -O1 (the optimisation ASan's authors recommend) keeps the simulation tests fast enough and
# compiles much faster than -O2; -g1 gives file:line in reports at a fraction of -g's cost.
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" -DCOSIM_SANITIZE=ON \
  >/dev/null
cmake --build "$BUILD" -j"$JOBS"

# MuJoCo and Mesa (OSMesa/llvmpipe) are not instrumented: lsan.supp names only those
# third-party libraries, never our code.
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1${COSIM_EXTRA_ASAN_OPTIONS:+:$COSIM_EXTRA_ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$ROOT/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$BUILD" --output-on-failure -j"$JOBS" "$@"
