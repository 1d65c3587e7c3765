#!/usr/bin/env bash
# Makes `import smpl_olympics` work for Debian's python3: points a .pth file in the user's site
# packages (or the active virtualenv's) at the package the build assembled in build/python.
# Run after deploy/build.sh; re-run nothing after rebuilding (it points at the build tree).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
python=${PYTHON:-python3}
[ -f "$repo/build/python/smpl_olympics/__init__.py" ] || { echo "build first: bash deploy/build.sh" >&2; exit 1; }
site=$("$python" -c 'import site, sys; print(site.getsitepackages()[0] if sys.prefix != sys.base_prefix else site.getusersitepackages())')
mkdir -p "$site"
echo "$repo/build/python" > "$site/smpl_olympics.pth"
"$python" -c 'import smpl_olympics, sys; print("smpl_olympics ready for", sys.executable)'
