#!/usr/bin/env bash
# A throwaway PostgreSQL for the record-store tests (ctest fixture pg_server): initdb into DIR, Unix socket
# in DIR only (listen_addresses=''), no network, fsync off (nothing here outlives the test run).
#   pg_test_server.sh start DIR     # fresh cluster; role "skillcoach" (trust), socket DIR/.s.PGSQL.5432
#   pg_test_server.sh stop DIR      # stops it and removes DIR
#   pg_test_server.sh pause DIR     # stops the server, keeps the data (the outage test)
#   pg_test_server.sh resume DIR    # starts it again on the same data
# Fails loudly when the PostgreSQL server binaries are missing (Debian: postgresql), unless
# SKILLCOACH_NO_POSTGRES=1 says there is no server here (the tests then skip).
set -euo pipefail
action=$1 dir=$2
if [ "${SKILLCOACH_NO_POSTGRES:-}" = 1 ]; then
  echo "pg_test_server.sh: SKILLCOACH_NO_POSTGRES=1: no server (the PostgreSQL tests skip)"
  exit 0
fi
bin=""
for candidate in /usr/lib/postgresql/*/bin; do [ -x "$candidate/initdb" ] && bin=$candidate; done
if [ -z "$bin" ]; then
  echo "pg_test_server.sh: no PostgreSQL server binaries (/usr/lib/postgresql/*/bin/initdb); install the" \
    "Debian package postgresql (scripts/setup.sh does)" >&2
  exit 1
fi
# PostgreSQL refuses to run as root: run it as the postgres user (the Debian package creates it), or nobody.
as_server=()
if [ "$(id -u)" -eq 0 ]; then
  user=postgres
  getent passwd postgres >/dev/null || user=nobody
  as_server=(runuser -u "$user" --)
fi
ctl() { "${as_server[@]}" "$bin/pg_ctl" -D "$dir/data" -l "$dir/server.log" "$@"; }
case "$action" in
  start)
    [ -d "$dir/data" ] && { ctl -m immediate stop >/dev/null 2>&1 || true; }
    rm -rf "$dir" && mkdir -p "$dir"
    [ ${#as_server[@]} -eq 0 ] || chown "$user" "$dir"
    "${as_server[@]}" "$bin/initdb" -D "$dir/data" -U skillcoach --auth=trust --locale=C -E UTF8 --no-sync \
      >"$dir/initdb.log" 2>&1 || { cat "$dir/initdb.log" >&2; exit 1; }
    ctl -w -o "-c listen_addresses='' -k $dir -c fsync=off -c full_page_writes=off -c max_connections=60" start \
      >/dev/null || { cat "$dir/server.log" >&2; exit 1; }
    ;;
  pause) ctl -w -m fast stop >/dev/null ;;
  resume) ctl -w -o "-c listen_addresses='' -k $dir -c fsync=off -c full_page_writes=off -c max_connections=60" \
    start >/dev/null ;;
  stop)
    [ -d "$dir/data" ] && { ctl -w -m fast stop >/dev/null 2>&1 || true; }
    rm -rf "$dir"
    ;;
  *) echo "usage: pg_test_server.sh start|stop|pause|resume DIR" >&2; exit 2 ;;
esac
