#!/bin/bash
# Makes `import cosim` work without PYTHONPATH: writes cosim.pth, one line naming the built
# package's folder (build/python), into the user's site-packages of the interpreter the module is
# built for; Python adds that folder to sys.path at start-up (docs/python.md). A link to the
# build, not a copy: the module reads the checkout's scenarios and models, and a rebuild updates
# it. Where that interpreter has user site-packages off, nothing is written and it says so. Where
# cosim.pth named another checkout's build, it says that `import cosim` now loads this one instead
# (cosim.__file__ and cosim.build_info() tell which build a Python session has loaded).
# Usage: python/install_user_path.sh BUILD_PYTHON_DIR [PYTHON]   (PYTHON: /usr/bin/python3)
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1/cosim" ]; then
  echo "install_user_path: ${1:-BUILD_PYTHON_DIR}: no built package cosim/ there" >&2
  exit 2
fi
dir=$(cd "$1" && pwd)
python=${2:-/usr/bin/python3}
if ! "$python" -c 'import site, sys; sys.exit(0 if site.ENABLE_USER_SITE else 1)'; then
  echo "setup: $python has user site-packages off; use PYTHONPATH=$dir to import cosim"
  exit 0
fi
site=$("$python" -m site --user-site)
mkdir -p "$site"
previous=""
if [ -f "$site/cosim.pth" ]; then previous=$(head -n 1 "$site/cosim.pth"); fi
# A temporary name first (Python reads only *.pth), so a half-written file is never read.
echo "$dir" >"$site/cosim.pth.tmp"
mv "$site/cosim.pth.tmp" "$site/cosim.pth"
if [ -n "$previous" ] && [ "$previous" != "$dir" ]; then
  echo "setup: import cosim (without PYTHONPATH) now loads $dir/cosim, no longer $previous/cosim ($site/cosim.pth)"
elif [ -z "$previous" ]; then
  echo "setup: import cosim (without PYTHONPATH) loads $dir/cosim ($site/cosim.pth)"
fi
