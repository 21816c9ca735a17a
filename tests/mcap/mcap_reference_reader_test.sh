#!/bin/bash
# A short run exported with `cosim export-mcap` and read back by the MCAP reference reader
# (@mcap/core from the npm registry, which ./setup.sh installs into build/node when npm is there).
# Exit 77 (CTest: skipped) without Node.js or the package.
# Usage: mcap_reference_reader_test.sh COSIM_BINARY NODE_MODULES_DIR WORK_DIR
set -euo pipefail
cosim=$1 modules=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v node > /dev/null; then
  echo "skipped: Node.js is not installed (Debian package nodejs)"; exit 77
fi
if [ ! -d "$modules/@mcap/core" ]; then
  echo "skipped: @mcap/core is not in $modules (./setup.sh installs it when npm is present:"
  echo "  npm install --prefix $(dirname "$modules") @mcap/core)"; exit 77
fi
rm -rf "$work"
# The default scenario on a short hop (about 4 s of flight), no pictures.
"$cosim" run --quiet --no-video --no-images --out "$work/run" \
  --set 'vehicles[0].goal=[6,5,2.5]' > "$work.log" 2>&1 || { cat "$work.log"; exit 1; }
"$cosim" export-mcap "$work/run"
node "$here/read_exported_mcap.mjs" "$work/run/run.mcap" "$modules"
rm -rf "$work" "$work.log"
