#!/usr/bin/env bash
# Makes `import smpl_olympics` work for the Python the build compiled the package for (Debian's
# /usr/bin/python3 when there is one: clients/CMakeLists.txt), whatever python3 is first on PATH:
# points a .pth file in its user site packages (or the active virtualenv's) at the package the
# build assembled in build/python. PYTHON=... picks another interpreter of the same version.
# Run after deploy/build.sh; re-run nothing after rebuilding (it points at the build tree).
# For any other Python: pip install ./clients/python into it (docs/clients.md).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
[ -f "$repo/build/python/smpl_olympics/__init__.py" ] || { echo "build first: bash deploy/build.sh" >&2; exit 1; }
built_for=$(sed -n 's/^OLYMPICS_PYTHON:INTERNAL=//p' "$repo/build/CMakeCache.txt" 2>/dev/null || true)
python=${PYTHON:-${built_for:-python3}}
echo "installing smpl_olympics for $python ($("$python" --version 2>&1)); the build compiled it for ${built_for:-an unknown Python}"
if ! "$python" -c 'import numpy' 2>/dev/null; then
  echo "$python has no numpy: install it there (Debian: sudo apt-get install python3-numpy), or run with PYTHON=${built_for:-/usr/bin/python3}" >&2
  exit 1
fi
site=$("$python" -c 'import site, sys; print(site.getsitepackages()[0] if sys.prefix != sys.base_prefix else site.getusersitepackages())')
mkdir -p "$site"
echo "$repo/build/python" > "$site/smpl_olympics.pth"
if ! "$python" -c 'import smpl_olympics' 2>/dev/null; then
  rm -f "$site/smpl_olympics.pth"
  echo "$python cannot load build/python's compiled module (built for ${built_for:-another Python}): run with PYTHON=${built_for:-<that python>}, or pip install ./clients/python into $python" >&2
  exit 1
fi
"$python" -c 'import smpl_olympics, sys; print("smpl_olympics ready for", sys.executable)'
