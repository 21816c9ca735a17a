#!/bin/bash
# Installs what cosim needs from Debian 12's packages (only what is missing) and builds it in
# build/. Usage: ./setup.sh [run|test|build]  (default: build)
#   ./setup.sh run   also runs the bundled default scenario (writes out/default/)
#   ./setup.sh test  also runs the whole test suite (CTest)
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(
  build-essential cmake pkg-config ccache ninja-build
  libmujoco-dev libqhull-dev          # physics (libqhull-dev: mujoco's CMake config needs its headers)
  libeigen3-dev liburdfdom-dev libtinyxml2-dev
  libosmesa6-dev                      # off-screen OpenGL, no display or GPU needed
  libnlopt-cxx-dev libyaml-cpp-dev libcli11-dev
  ffmpeg                              # H.264 video and PNG output
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev                  # JSON: what cosim writes and reads back (core/)
  libompl-dev libboost-graph-dev libnanoflann-dev   # peers for the benchmarks, k-d tree
  gnuplot-nox                         # figures
  chromium                            # the HTML report test opens the report headless
  libjs-three                         # three.js, embedded in every run's viewer.html
  pybind11-dev python3-dev python3-numpy   # the Python module (build/python, `import cosim`)
  python3-pytest python3-matplotlib        # its tests and examples
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

JOBS=$(nproc 2>/dev/null || echo 2)
# ccache keys on paths relative to the checkout, so another clone of the project reuses the cache.
export CCACHE_BASEDIR="$PWD"
case "${1:-build}" in
  run|test|build) ;;
  *) echo "usage: $0 [run|test|build]" >&2; exit 2 ;;
esac
# Ninja: less work per file than make, and it keeps the machine busy across libraries. A build
# folder made earlier keeps the generator it was made with (CMake ignores this then).
if command -v ninja >/dev/null 2>&1; then export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
# The MCAP reference reader (@mcap/core, npm registry) for the export test, once; without npm or
# the registry the test is skipped, and the setup goes on.
if [ "${1:-build}" != run ] && command -v npm >/dev/null 2>&1 &&
   [ ! -d build/node/node_modules/@mcap/core ]; then
  if ! npm install --prefix build/node --no-audit --no-fund @mcap/core@2 >build/npm-install.log 2>&1
  then
    echo "setup: could not install @mcap/core from npm (the MCAP reader test will be skipped):"
    tail -n 5 build/npm-install.log | sed 's/^/setup:   /'
  fi
fi
# `run` builds only the program it runs and the Python module (not the test suite); `test` and
# `build` build everything.
case "${1:-build}" in
  run)  cmake --build build -j"$JOBS" --target cosim _cosim ;;
  *)    cmake --build build -j"$JOBS" ;;
esac
# `import cosim` without PYTHONPATH: cosim.pth in the user's site-packages names build/python
# (docs/python.md).
if [ -d build/python/cosim ] && [ -x /usr/bin/python3 ]; then
  python/install_user_path.sh build/python
fi
case "${1:-build}" in
  run)  build/cosim run --out out/default ;;
  test) ctest --test-dir build --output-on-failure -j"$JOBS" ;;
esac
