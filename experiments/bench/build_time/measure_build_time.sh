#!/bin/bash
# Measures the CPU seconds (user + system, every compiler and linker process added up) of a cold
# build of cosim: a fresh build folder, ccache off. Wall time means little on a shared machine,
# so the script also compiles one fixed translation unit (reference_tu.cpp beside this script)
# with the project's flags in the same run and reports each build as a multiple of it: that ratio
# compares across runs, machines and loads.
set -euo pipefail

usage() {
  cat <<'USAGE'
Usage: experiments/bench/build_time/measure_build_time.sh [options]
Configures a fresh build folder with ccache off, builds the targets one after the other and
prints the CPU seconds of each step next to those of one reference translation unit.
  --source DIR          source tree to build (default: this checkout)
  --build DIR           build folder, deleted first (default: /tmp/cosim_build_time)
  --targets "T1 T2 .."  targets built in this order; each line also gives the sum so far
                        (default: "cosim all": the program, then everything else)
  --jobs N              parallel jobs (default: 2)
  --generator NAME      CMake generator (default: CMake's, or CMAKE_GENERATOR)
  --cmake-arg ARG       extra configure argument (repeatable), e.g. --cmake-arg -DCOSIM_WITH_SIM=OFF
  --reference-runs N    compiles of the reference unit before and after the build (default: 3)
  --per-tu FILE         also log the CPU seconds of every compile and link to FILE
                        ("user system output" per line) and print the costliest ones
  -h, --help            this text
Output lines start with "build_time:"; the ratio is build CPU s / reference CPU s.
USAGE
}

HERE=$(cd "$(dirname "$0")" && pwd)
SOURCE=$(cd "$HERE/../../.." && pwd)
BUILD=/tmp/cosim_build_time
TARGETS="cosim all"
JOBS=2
GENERATOR=""
CMAKE_ARGS=()
REF_RUNS=3
PER_TU=""
while [ $# -gt 0 ]; do
  case "$1" in
    --source) SOURCE=$(cd "$2" && pwd); shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --targets) TARGETS=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --generator) GENERATOR=$2; shift 2 ;;
    --cmake-arg) CMAKE_ARGS+=("$2"); shift 2 ;;
    --reference-runs) REF_RUNS=$2; shift 2 ;;
    --per-tu) PER_TU=$(realpath -m "$2"); shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "measure_build_time.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -x /usr/bin/time ] || { echo "measure_build_time.sh: needs /usr/bin/time (Debian: time)" >&2; exit 2; }
REFERENCE=$HERE/reference_tu.cpp
SCRATCH=$(mktemp -d)
trap 'rm -rf "$SCRATCH"' EXIT

# ccache off both ways: the environment (honoured by any ccache launcher) and an empty launcher.
export CCACHE_DISABLE=1
CXX_REAL=$(command -v "${CXX:-c++}")
CXX_USED=$CXX_REAL
if [ -n "$PER_TU" ]; then
  # A compiler wrapper that appends "user system output-file" for every compile and link.
  : >"$PER_TU"
  CXX_USED=$SCRATCH/cxx_cpu_log
  cat >"$CXX_USED" <<WRAP
#!/bin/bash
out=-; prev=
for a in "\$@"; do [ "\$prev" = -o ] && out=\$a; prev=\$a; done
exec /usr/bin/time -f "%U %S \${out//%/%%}" -a -o "$PER_TU" "$CXX_REAL" "\$@"
WRAP
  chmod +x "$CXX_USED"
fi

# Runs "$@" and prints its children's user + system CPU seconds.
cpu_seconds() {
  /usr/bin/time -f "%U %S" -o "$SCRATCH/cpu" "$@" >>"$LOG" 2>&1 || {
    echo "measure_build_time.sh: failed: $* (last lines of $LOG:)" >&2
    tail -n 30 "$LOG" >&2
    exit 1
  }
  awk '{ printf "%.2f", $1 + $2 }' "$SCRATCH/cpu"
}

rm -rf "$BUILD"
mkdir -p "$BUILD"
LOG=$BUILD/measure_build_time.log  # what the configure and the builds printed (warnings too)
generator_args=()
[ -n "$GENERATOR" ] && generator_args=(-G "$GENERATOR")
configure_cpu=$(cpu_seconds cmake -S "$SOURCE" -B "$BUILD" "${generator_args[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$CXX_USED" -DCMAKE_CXX_COMPILER_LAUNCHER= \
  "${CMAKE_ARGS[@]}")
[ -n "$PER_TU" ] && : >"$PER_TU"  # compiler checks of the configure step are not the build

# The project's flags for the reference unit: the build type's, the standard and the warnings.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$BUILD/CMakeCache.txt"; }
REF_FLAGS="$(cache_value CMAKE_CXX_FLAGS) $(cache_value CMAKE_CXX_FLAGS_RELEASE) -std=c++20 -Wall -Wextra -fPIC"
reference_total=0
reference_runs() {
  local i s
  for ((i = 0; i < REF_RUNS; i++)); do
    # shellcheck disable=SC2086
    s=$(cpu_seconds "$CXX_REAL" $REF_FLAGS -c "$REFERENCE" -o "$SCRATCH/reference.o")
    reference_total=$(awk -v a="$reference_total" -v b="$s" 'BEGIN { printf "%.2f", a + b }')
  done
}

reference_runs
echo "build_time: source $SOURCE, build $BUILD, -j$JOBS, generator $(cache_value CMAKE_GENERATOR)"
echo "build_time: build output in $LOG"
echo "build_time: configure $configure_cpu s CPU (not in the sums below)"
echo "build_time: reference unit before the build $(awk -v t="$reference_total" -v n="$REF_RUNS" \
  'BEGIN { printf "%.3f", t / n }') s CPU (mean of $REF_RUNS compiles)"
sum=0
results=()
for target in $TARGETS; do
  s=$(cpu_seconds cmake --build "$BUILD" -j"$JOBS" --target "$target")
  sum=$(awk -v a="$sum" -v b="$s" 'BEGIN { printf "%.2f", a + b }')
  results+=("$target $s $sum")
  echo "build_time: built $target: $s s CPU (sum so far $sum s)"
done
reference_runs
reference=$(awk -v t="$reference_total" -v n="$REF_RUNS" 'BEGIN { printf "%.3f", t / (2 * n) }')
echo "build_time: reference unit $reference s CPU (mean of $((2 * REF_RUNS)) compiles, $REF_FLAGS)"
printf 'build_time: %-12s %10s %10s %12s\n' target "step CPU s" "sum CPU s" "sum/ref"
for r in "${results[@]}"; do
  read -r target s total <<<"$r"
  ratio=$(awk -v a="$total" -v b="$reference" 'BEGIN { printf "%.1f", a / b }')
  printf 'build_time: %-12s %10s %10s %12s\n' "$target" "$s" "$total" "$ratio"
done

echo "build_time: compiler warnings: $(grep -c 'warning:' "$LOG" || true)"

if [ -n "$PER_TU" ]; then
  echo "build_time: costliest compiles and links (CPU s, from $PER_TU):"
  awk '{ printf "%8.2f %s\n", $1 + $2, $3 }' "$PER_TU" | sort -rn | head -n 25 |
    sed "s|$BUILD/||; s|^|build_time:   |"
  echo "build_time: CPU s by target (compiles), and links:"
  awk '{ f = "links"; if (match($3, /[^\/]*\.dir\//)) f = substr($3, RSTART, RLENGTH - 5);
         t[f] += $1 + $2 } END { for (k in t) printf "%8.1f %s\n", t[k], k }' "$PER_TU" |
    sort -rn | sed 's|^|build_time:   |'
fi
