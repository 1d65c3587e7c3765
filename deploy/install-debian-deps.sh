#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds against (deploy/debian-packages.txt), and
# with --tests also those only the tests need (deploy/debian-test-packages.txt).
# Runs as root, or through sudo when there is one.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
as_root=()
if [ "$(id -u)" != 0 ]; then as_root=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -q
lists=("$here/debian-packages.txt")
if [ "${1:-}" = --tests ]; then lists+=("$here/debian-test-packages.txt"); fi
# shellcheck disable=SC2046
"${as_root[@]}" apt-get install -y -q --no-install-recommends $(cat "${lists[@]}" | grep -v '^#')
