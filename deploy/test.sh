#!/usr/bin/env bash
# The test command: installs the Debian packages, builds, starts a local PostgreSQL for the
# PostgreSQL-backed tests, makes sure LCM has a multicast route, and runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-debian-deps.sh --tests
bash deploy/build.sh
bash deploy/install-python-test-deps.sh
bash deploy/multicast-route.sh
OLYMPICS_TEST_POSTGRES_URL=$(bash deploy/start-test-postgres.sh | tail -1)
export OLYMPICS_TEST_POSTGRES_URL
ctest --test-dir build --output-on-failure --timeout 600
