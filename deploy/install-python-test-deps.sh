#!/usr/bin/env bash
# Installs the pinned Python packages the tests need from the package index
# (clients/python/test-requirements.txt: PettingZoo and Gymnasium, whose own conformance tests
# tests/python/test_pettingzoo.py runs; deploy/test-requirements.txt: kubernetes-validate, the
# Kubernetes API schemas tests/deploy/validate_manifests.py checks the manifests against) into the Python the build uses for its tests: Debian's
# /usr/bin/python3 (clients/CMakeLists.txt), or $PYTHON. Debian marks its Python "externally
# managed", so this installs into the user's site packages with --break-system-packages; Debian's
# own numpy is pinned as a constraint, so nothing here replaces it.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
python=${PYTHON:-/usr/bin/python3}
[ -x "$python" ] || python=$(command -v python3)
constraints=$(mktemp)
trap 'rm -f "$constraints"' EXIT
"$python" -c 'import numpy; print("numpy==" + numpy.__version__)' > "$constraints"
echo "Python test packages for $python ($("$python" --version 2>&1)):"
# Into a virtualenv's own site packages when PYTHON is one's; else the user's.
where=(--user --break-system-packages)
if "$python" -c 'import sys; sys.exit(sys.prefix == sys.base_prefix)'; then where=(); fi
"$python" -m pip install "${where[@]}" --quiet --disable-pip-version-check \
  -r "$repo/clients/python/test-requirements.txt" -r "$repo/deploy/test-requirements.txt" \
  -c "$constraints"
"$python" -c 'import pettingzoo, gymnasium, numpy
print("pettingzoo", pettingzoo.__version__, "gymnasium", gymnasium.__version__, "numpy", numpy.__version__)'
