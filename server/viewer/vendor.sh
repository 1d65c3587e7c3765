#!/usr/bin/env bash
# Re-bundles the viewer's npm dependencies (package.json, pinned by package-lock.json) into
# vendor/viewer-deps.js, the one file the pages load. The result is committed: building the
# project and watching a match need neither node nor the network; only changing a dependency
# does (then run this and commit vendor/).
set -euo pipefail
cd "$(dirname "$0")"
npm ci --no-audit --no-fund
npx esbuild deps-entry.js --bundle --minify --format=iife --legal-comments=none \
  --outfile=vendor/viewer-deps.js
{
  echo "vendor/viewer-deps.js bundles these npm packages (versions: package-lock.json):"
  for p in three fzstd; do
    echo; echo "== $p $(node -p "require('./node_modules/$p/package.json').version") =="
    cat "node_modules/$p/LICENSE"*
  done
} > vendor/LICENSES.txt
rm -rf node_modules
