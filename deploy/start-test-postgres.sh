#!/usr/bin/env bash
# Starts Debian's PostgreSQL cluster and makes a role and database for the tests; prints the URL
# to export as OLYMPICS_TEST_POSTGRES_URL. Idempotent. Needs root (it acts as user postgres).
set -euo pipefail
version=$(ls /usr/lib/postgresql | sort -n | tail -1)
if ! pg_lsclusters -h | awk '{print $2}' | grep -qx main; then
  pg_createcluster "$version" main >/dev/null
fi
pg_ctlcluster "$version" main start 2>/dev/null || true
pg_isready -q -t 30 -h 127.0.0.1
as_postgres() { runuser -u postgres -- "$@"; }
as_postgres psql -qAt -c "SELECT 1 FROM pg_roles WHERE rolname = 'olympics'" | grep -q 1 ||
  as_postgres psql -q -c "CREATE ROLE olympics LOGIN PASSWORD 'olympics'"
as_postgres psql -qAt -c "SELECT 1 FROM pg_database WHERE datname = 'olympics_test'" | grep -q 1 ||
  as_postgres createdb -O olympics olympics_test
echo "postgresql://olympics:olympics@127.0.0.1:5432/olympics_test"
